/* Equirectangular panoramas from cube faces (app/output/panorama.h). */
#include "app/output/panorama.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

const char *app_pano_face_name(int face)
{
    static const char *const names[6] = {"front", "right", "back", "left", "up", "down"};
    return face >= 0 && face < 6 ? names[face] : "?";
}

static void cross(const float a[3], const float b[3], float out[3])
{
    float r[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    memcpy(out, r, sizeof r);
}

static float dot(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void normalize(float v[3])
{
    float n = sqrtf(dot(v, v));
    if (n > 0.0f)
        for (int k = 0; k < 3; k++)
            v[k] /= n;
}

void app_pano_frames(const float look[3], float fwd[6][3], float up[6][3])
{
    float f[3] = {look[0], look[1], 0.0f};
    if (!(dot(f, f) > 1e-12f)) {
        f[0] = 0.0f; /* looking straight up or down: face +Y */
        f[1] = 1.0f;
    }
    normalize(f);
    const float z[3] = {0, 0, 1};
    float r[3];
    cross(f, z, r);
    for (int k = 0; k < 3; k++) {
        fwd[APP_PANO_FRONT][k] = f[k];
        fwd[APP_PANO_RIGHT][k] = r[k];
        fwd[APP_PANO_BACK][k] = -f[k];
        fwd[APP_PANO_LEFT][k] = -r[k];
        fwd[APP_PANO_UP][k] = z[k];
        fwd[APP_PANO_DOWN][k] = -z[k];
        for (int s = 0; s < 4; s++)
            up[s][k] = z[k];
        up[APP_PANO_UP][k] = -f[k];
        up[APP_PANO_DOWN][k] = f[k];
    }
}

/* One face's camera basis exactly as glm_lookat makes it: right = fwd x up, up' = right x fwd. */
typedef struct face_basis {
    float f[3], r[3], u[3];
} face_basis;

static void bilinear(const uint8_t *img, int side, float x, float y, float acc[4])
{
    x = fminf(fmaxf(x, 0.0f), (float)side - 1.0f);
    y = fminf(fmaxf(y, 0.0f), (float)side - 1.0f);
    int x0 = (int)x, y0 = (int)y;
    int x1 = x0 + 1 < side ? x0 + 1 : x0, y1 = y0 + 1 < side ? y0 + 1 : y0;
    float fx = x - (float)x0, fy = y - (float)y0;
    for (int c = 0; c < 4; c++) {
        float a = img[((size_t)y0 * side + x0) * 4 + c], b = img[((size_t)y0 * side + x1) * 4 + c];
        float d = img[((size_t)y1 * side + x0) * 4 + c], e = img[((size_t)y1 * side + x1) * 4 + c];
        acc[c] += (a + (b - a) * fx) * (1.0f - fy) + (d + (e - d) * fx) * fy;
    }
}

void app_pano_equirect(const uint8_t *const faces[6], int face, const float fwd[6][3],
                       const float up[6][3], uint8_t *out, int w, int h)
{
    face_basis b[6];
    for (int k = 0; k < 6; k++) {
        memcpy(b[k].f, fwd[k], sizeof b[k].f);
        cross(fwd[k], up[k], b[k].r);
        normalize(b[k].r);
        cross(b[k].r, fwd[k], b[k].u);
    }
    const float *f = fwd[APP_PANO_FRONT], *r = fwd[APP_PANO_RIGHT], *z = fwd[APP_PANO_UP];
    const float pi = 3.14159265358979f;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float acc[4] = {0, 0, 0, 0};
            for (int s = 0; s < 4; s++) {
                float theta =
                    2.0f * pi * ((float)x + 0.25f + 0.5f * (float)(s & 1)) / (float)w - pi;
                float phi = 0.5f * pi - pi * ((float)y + 0.25f + 0.5f * (float)(s >> 1)) / (float)h;
                float d[3];
                for (int k = 0; k < 3; k++)
                    d[k] = cosf(phi) * (cosf(theta) * f[k] + sinf(theta) * r[k]) + sinf(phi) * z[k];
                int best = 0;
                float best_dot = -2.0f;
                for (int k = 0; k < 6; k++) {
                    float c = dot(d, b[k].f);
                    if (c > best_dot) {
                        best_dot = c;
                        best = k;
                    }
                }
                float ndc_x = dot(d, b[best].r) / best_dot, ndc_y = dot(d, b[best].u) / best_dot;
                bilinear(faces[best], face, (ndc_x + 1.0f) * 0.5f * (float)face - 0.5f,
                         (1.0f - ndc_y) * 0.5f * (float)face - 0.5f, acc);
            }
            for (int c = 0; c < 4; c++)
                out[((size_t)y * w + x) * 4 + c] = (uint8_t)fminf(acc[c] * 0.25f + 0.5f, 255.0f);
        }
}

int app_pano_xmp(int w, int h, char *out, size_t size)
{
    int n =
        snprintf(out, size,
                 "<?xpacket begin=\"\xEF\xBB\xBF\" id=\"W5M0MpCehiHzreSzNTczkc9d\"?>\n"
                 "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\">\n"
                 " <rdf:RDF xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\">\n"
                 "  <rdf:Description rdf:about=\"\"\n"
                 "    xmlns:GPano=\"http://ns.google.com/photos/1.0/panorama/\">\n"
                 "   <GPano:ProjectionType>equirectangular</GPano:ProjectionType>\n"
                 "   <GPano:UsePanoramaViewer>True</GPano:UsePanoramaViewer>\n"
                 "   <GPano:FullPanoWidthPixels>%d</GPano:FullPanoWidthPixels>\n"
                 "   <GPano:FullPanoHeightPixels>%d</GPano:FullPanoHeightPixels>\n"
                 "   <GPano:CroppedAreaImageWidthPixels>%d</GPano:CroppedAreaImageWidthPixels>\n"
                 "   <GPano:CroppedAreaImageHeightPixels>%d</GPano:CroppedAreaImageHeightPixels>\n"
                 "   <GPano:CroppedAreaLeftPixels>0</GPano:CroppedAreaLeftPixels>\n"
                 "   <GPano:CroppedAreaTopPixels>0</GPano:CroppedAreaTopPixels>\n"
                 "  </rdf:Description>\n"
                 " </rdf:RDF>\n"
                 "</x:xmpmeta>\n"
                 "<?xpacket end=\"w\"?>",
                 w, h, w, h);
    return n >= 0 && (size_t)n < size ? n : -1;
}
