// Writing a scene of named, transformed nodes as GLB with tinygltf (catalog/scene_write.h). The
// helpers shared with the model writer are in gltf_write_common.h.
#include "gltf_write_common.h"

#include "catalog/scene_write.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using cat_gltf::add_accessor;
using cat_gltf::add_view;
using cat_gltf::fail;

namespace
{

// C: Tessera (x, y, z) mm -> glTF (x, z, -y) m, as a 3x3 rotation A (row-major) and 1/1000.
const double A[3][3] = {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};

// C * M * C^-1 for a column-major M: linear part A L A^T (the scale cancels), translation
// A t / 1000.
void node_matrix(const double m[16], std::vector<double> &out)
{
    double l[3][3], t[3];
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++)
            l[r][c] = m[c * 4 + r];
        t[r] = m[12 + r];
    }
    out.assign(16, 0.0);
    bool identity = true;
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
            double s = 0;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    s += A[r][i] * l[i][j] * A[c][j];
            out[static_cast<size_t>(c * 4 + r)] = s;
            identity = identity && s == (r == c ? 1.0 : 0.0);
        }
        double s = 0;
        for (int i = 0; i < 3; i++)
            s += A[r][i] * t[i];
        out[static_cast<size_t>(12 + r)] = s / 1000.0;
        identity = identity && s == 0.0;
    }
    out[15] = 1.0;
    if (identity)
        out.clear(); // glTF's default; validators flag an explicit identity matrix
}

cat_result add_part(const char *path, const cat_scene *s, int node, int part, const cat_mesh &cm,
                    tinygltf::Model &m, tinygltf::Primitive &prim, char *err, size_t err_size)
{
    char where[160];
    std::snprintf(where, sizeof where, "node %d (\"%s\"), part %d", node, s->nodes[node].name,
                  part);
    cat_result r =
        cat_gltf::add_part_positions(path, where, cm, s->material_count, m, prim, err, err_size);
    if (r != CAT_OK)
        return r;
    size_t nv = static_cast<size_t>(cm.vertex_count);
    if (cm.normals) {
        std::vector<float> n(nv * 3);
        for (size_t v = 0; v < nv; v++) {
            const float *q = cm.normals + 3 * v;
            float x = q[0], y = q[2], z = -q[1];
            float len = std::sqrt(x * x + y * y + z * z);
            if (!(len > 0.0f) || !std::isfinite(len)) { // glTF wants unit normals
                x = 0;
                y = 1;
                z = 0;
                len = 1;
            }
            n[3 * v] = x / len;
            n[3 * v + 1] = y / len;
            n[3 * v + 2] = z / len;
        }
        prim.attributes["NORMAL"] =
            add_accessor(m, add_view(m, n.data(), n.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                         TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
    }
    // No TEXCOORD_0: no textures are written, and validators flag unused coordinates.
    return cat_gltf::add_part_indices(path, where, cm, m, prim, err, err_size);
}

// A camera node: in glTF space (C applied to eye, target and up) the node's -Z looks at the
// target and its +Y is the up vector made perpendicular (a look-at frame, rigid).
cat_result add_camera(const char *path, const cat_scene_camera &c, int index, tinygltf::Model &m,
                      char *err, size_t err_size)
{
    double eye[3], dir[3], up[3];
    for (int r = 0; r < 3; r++) {
        eye[r] = dir[r] = up[r] = 0;
        for (int k = 0; k < 3; k++) {
            eye[r] += A[r][k] * c.eye_mm[k] / 1000.0;
            dir[r] += A[r][k] * (c.eye_mm[k] - c.target_mm[k]); // the camera's +Z
            up[r] += A[r][k] * c.up[k];
        }
    }
    auto norm = [](double v[3]) {
        double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(l > 1e-12) || !std::isfinite(l))
            return false;
        for (int k = 0; k < 3; k++)
            v[k] /= l;
        return true;
    };
    auto cross = [](const double a[3], const double b[3], double out[3]) {
        out[0] = a[1] * b[2] - a[2] * b[1];
        out[1] = a[2] * b[0] - a[0] * b[2];
        out[2] = a[0] * b[1] - a[1] * b[0];
    };
    double x[3];
    bool ok = norm(dir);
    cross(up, dir, x);
    if (ok && !norm(x)) { // up along the view (looking straight down): any other up will do
        const double alt[2][3] = {{0, 0, -1}, {1, 0, 0}};
        for (int a = 0; a < 2; a++) {
            cross(alt[a], dir, x);
            if (norm(x))
                break;
        }
    }
    if (!ok || !norm(x) || !(c.yfov_deg > 0 && c.yfov_deg < 180) || !(c.aspect >= 0))
        return fail(path, err, err_size, CAT_ERR_INVALID,
                    "camera %d (\"%s\"): degenerate view (the eye on the target or a bad field "
                    "of view)",
                    index, c.name);
    double y[3] = {dir[1] * x[2] - dir[2] * x[1], dir[2] * x[0] - dir[0] * x[2],
                   dir[0] * x[1] - dir[1] * x[0]};
    tinygltf::Camera cam;
    cam.type = "perspective";
    cam.name = std::string(c.name, strnlen(c.name, sizeof c.name));
    cam.perspective.yfov = c.yfov_deg * 3.14159265358979323846 / 180.0;
    cam.perspective.znear = 0.01; // 10 mm: Tessera's cameras stand inside small rooms
    cam.perspective.zfar = c.zfar_mm > 10.0 ? c.zfar_mm / 1000.0 : 100.0;
    cam.perspective.aspectRatio = c.aspect;
    m.cameras.push_back(cam);
    tinygltf::Node node;
    node.name = cam.name;
    node.camera = static_cast<int>(m.cameras.size() - 1);
    node.matrix = {x[0],   x[1],   x[2],   0, y[0],   y[1],   y[2],   0,
                   dir[0], dir[1], dir[2], 0, eye[0], eye[1], eye[2], 1};
    m.nodes.push_back(node);
    return CAT_OK;
}

cat_result build(const char *path, const cat_scene *s, tinygltf::Model &m, char *err,
                 size_t err_size)
{
    m.asset.version = "2.0";
    m.asset.generator = "Tessera project exporter";
    m.buffers.resize(1);
    cat_gltf::add_materials(m, s->materials, s->material_count, s->extras);
    tinygltf::Scene scene;
    for (int i = 0; i < s->node_count; i++) {
        const cat_scene_node &sn = s->nodes[i];
        if (sn.parent < -1 || sn.parent >= i)
            return fail(path, err, err_size, CAT_ERR_INVALID,
                        "node %d (\"%s\"): parent %d is not an earlier node", i, sn.name,
                        sn.parent);
        for (int k = 0; k < 16; k++)
            if (!std::isfinite(sn.matrix[k]))
                return fail(path, err, err_size, CAT_ERR_INVALID,
                            "node %d (\"%s\"): its transform is not finite", i, sn.name);
        if (sn.part_count < 0 || (sn.part_count > 0 && !sn.parts))
            return fail(path, err, err_size, CAT_ERR_INVALID, "node %d (\"%s\"): bad parts", i,
                        sn.name);
        tinygltf::Node node;
        node.name = std::string(sn.name, strnlen(sn.name, sizeof sn.name));
        node_matrix(sn.matrix, node.matrix);
        if (sn.part_count > 0) {
            tinygltf::Mesh mesh;
            mesh.name = node.name;
            for (int k = 0; k < sn.part_count; k++) {
                tinygltf::Primitive prim;
                cat_result r = add_part(path, s, i, k, sn.parts[k], m, prim, err, err_size);
                if (r != CAT_OK)
                    return r;
                mesh.primitives.push_back(prim);
            }
            m.meshes.push_back(mesh);
            node.mesh = static_cast<int>(m.meshes.size() - 1);
        }
        m.nodes.push_back(node);
        if (sn.parent < 0)
            scene.nodes.push_back(i);
        else
            m.nodes[static_cast<size_t>(sn.parent)].children.push_back(i);
    }
    for (int i = 0; i < s->camera_count; i++) {
        cat_result r = add_camera(path, s->cameras[i], i, m, err, err_size);
        if (r != CAT_OK)
            return r;
        m.nodes[0].children.push_back(static_cast<int>(m.nodes.size() - 1));
    }
    m.scenes.push_back(scene);
    m.defaultScene = 0;
    return CAT_OK;
}

} // namespace

extern "C" void cat_scene_identity(double m[16])
{
    for (int k = 0; k < 16; k++)
        m[k] = k % 5 == 0 ? 1.0 : 0.0;
}

extern "C" cat_result cat_scene_write_glb(const char *path, const cat_scene *s, char *err,
                                          size_t err_size)
{
    if (err && err_size)
        err[0] = 0;
    if (!path || !*path)
        return fail("(no file)", err, err_size, CAT_ERR_INVALID, "no output path");
    if (!s || s->node_count <= 0 || !s->nodes || s->material_count < 0 ||
        (s->material_count > 0 && !s->materials) || s->camera_count < 0 ||
        (s->camera_count > 0 && !s->cameras))
        return fail(path, err, err_size, CAT_ERR_INVALID, "the scene has no nodes");
    return cat_gltf::guarded(path, err, err_size, [&] {
        tinygltf::Model m;
        cat_result r = build(path, s, m, err, err_size);
        return r == CAT_OK ? cat_gltf::write_glb(path, m, err, err_size) : r;
    });
}
