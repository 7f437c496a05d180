// Writing models as GLB with tinygltf (catalog/model_write.h), and reading back the Tessera
// extras of a file's materials. tinygltf's implementation is compiled once, in gltf_load.cpp,
// with the same configuration macros as below; this file only uses its classes. The bytes are
// serialised into memory and written by write_atomic(): a temporary file in the same folder,
// fsync, rename, so a reader sees the old file or the whole new one.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <fstream> // tiny_gltf.h 2.7 uses std::ofstream but includes <fstream> only with its FS code
#include <tiny_gltf.h>

#include "catalog/model_write.h"
#include "model_internal.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fcntl.h>
#include <new>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace
{

cat_result fail(const char *path, char *err, size_t size, cat_result code, const char *fmt, ...)
{
    if (!err || !size)
        return code;
    int n = std::snprintf(err, size, "%s: ", path ? path : "(no file)");
    if (n < 0 || static_cast<size_t>(n) >= size)
        return code;
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(err + n, size - static_cast<size_t>(n), fmt, ap);
    va_end(ap);
    return code;
}

// Appends bytes to the single buffer, 4-byte aligned, and returns a new buffer view's index.
int add_view(tinygltf::Model &m, const void *data, size_t bytes, int target)
{
    std::vector<unsigned char> &buf = m.buffers[0].data;
    while (buf.size() % 4)
        buf.push_back(0);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = buf.size();
    v.byteLength = bytes;
    v.target = target;
    const unsigned char *p = static_cast<const unsigned char *>(data);
    buf.insert(buf.end(), p, p + bytes);
    m.bufferViews.push_back(v);
    return static_cast<int>(m.bufferViews.size() - 1);
}

int add_accessor(tinygltf::Model &m, int view, int component, int type, size_t count)
{
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = component;
    a.type = type;
    a.count = count;
    m.accessors.push_back(a);
    return static_cast<int>(m.accessors.size() - 1);
}

// The shortest decimal that reads back as the same float: extras say 0.05, not
// 0.05000000074505806 (the float widened to double), and still round-trip exactly.
tinygltf::Value num(float v)
{
    char text[32];
    for (int digits = 6; digits <= 9; digits++) {
        std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(v));
        if (static_cast<float>(std::strtod(text, nullptr)) == v)
            break;
    }
    return tinygltf::Value(std::strtod(text, nullptr));
}

tinygltf::Value rgb(const float c[3])
{
    tinygltf::Value::Array a;
    for (int k = 0; k < 3; k++)
        a.push_back(num(c[k]));
    return tinygltf::Value(a);
}

tinygltf::Value extras_value(const cat_material_extras &e)
{
    const cat_render_material &r = e.params;
    tinygltf::Value::Object t;
    t["ambient"] = rgb(r.ambient);
    t["diffuse"] = rgb(r.diffuse);
    t["specular"] = rgb(r.specular);
    t["emissive"] = rgb(r.emissive);
    t["shininess"] = num(r.shininess);
    t["k_r"] = num(r.reflectivity);
    t["g"] = num(r.glossiness);
    t["blend"] = tinygltf::Value(std::string(cat_blend_name(r.blend)));
    t["transparency"] = num(r.transparency);
    t["ior"] = num(r.ior);
    t["variant_slot"] = tinygltf::Value(e.variant_slot != 0);
    tinygltf::Value::Object o;
    o["tessera"] = tinygltf::Value(t);
    return tinygltf::Value(o);
}

cat_result write_atomic(const char *path, const std::string &bytes, char *err, size_t err_size)
{
    std::string tmp = std::string(path) + ".tmp-XXXXXX";
    std::vector<char> name(tmp.begin(), tmp.end());
    name.push_back(0);
    int fd = mkstemp(name.data());
    if (fd < 0)
        return fail(path, err, err_size, CAT_ERR_IO, "cannot create a temporary file: %s",
                    std::strerror(errno));
    size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            int e = errno;
            close(fd);
            unlink(name.data());
            return fail(path, err, err_size, CAT_ERR_IO, "write failed: %s", std::strerror(e));
        }
        done += static_cast<size_t>(n);
    }
    fchmod(fd, 0644);
    if (fsync(fd) != 0 || close(fd) != 0) {
        int e = errno;
        unlink(name.data());
        return fail(path, err, err_size, CAT_ERR_IO, "write failed: %s", std::strerror(e));
    }
    if (std::rename(name.data(), path) != 0) {
        int e = errno;
        unlink(name.data());
        return fail(path, err, err_size, CAT_ERR_IO, "cannot rename the temporary file: %s",
                    std::strerror(e));
    }
    return CAT_OK;
}

cat_result build(const char *path, const cat_model *src, const cat_material_extras *extras,
                 tinygltf::Model &m, char *err, size_t err_size)
{
    m.asset.version = "2.0";
    m.asset.generator = "Tessera model writer";
    m.buffers.resize(1);
    for (int i = 0; i < src->material_count; i++) {
        const cat_material &cm = src->materials[i];
        tinygltf::Material mat;
        mat.name = std::string(cm.name, strnlen(cm.name, sizeof cm.name));
        mat.pbrMetallicRoughness.baseColorFactor.assign(cm.base_color, cm.base_color + 4);
        mat.pbrMetallicRoughness.metallicFactor = cm.metallic;
        mat.pbrMetallicRoughness.roughnessFactor = cm.roughness;
        mat.emissiveFactor.assign(cm.emissive, cm.emissive + 3);
        if (cm.base_color[3] < 1.0f)
            mat.alphaMode = "BLEND";
        if (extras && extras[i].present)
            mat.extras = extras_value(extras[i]);
        m.materials.push_back(mat);
    }
    tinygltf::Scene scene;
    for (int i = 0; i < src->mesh_count; i++) {
        const cat_mesh &cm = src->meshes[i];
        if (!cm.positions || !cm.indices || cm.vertex_count <= 0 || cm.index_count <= 0 ||
            cm.index_count % 3)
            return fail(path, err, err_size, CAT_ERR_INVALID,
                        "part %d has no triangles or no positions", i);
        if (cm.material < -1 || cm.material >= src->material_count)
            return fail(path, err, err_size, CAT_ERR_INVALID, "part %d: material %d out of range",
                        i, cm.material);
        size_t nv = static_cast<size_t>(cm.vertex_count);
        // Z-up millimetres to glTF's Y-up metres: (x, y, z) -> (x, z, -y) / 1000.
        std::vector<float> p(nv * 3), n;
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t v = 0; v < nv; v++) {
            const float *q = cm.positions + 3 * v;
            float g[3] = {q[0] / 1000.0f, q[2] / 1000.0f, -q[1] / 1000.0f};
            for (int k = 0; k < 3; k++) {
                if (!std::isfinite(g[k]))
                    return fail(path, err, err_size, CAT_ERR_INVALID,
                                "part %d: vertex %zu is not finite", i, v);
                p[3 * v + k] = g[k];
                lo[k] = std::min(lo[k], static_cast<double>(g[k]));
                hi[k] = std::max(hi[k], static_cast<double>(g[k]));
            }
        }
        tinygltf::Primitive prim;
        prim.mode = TINYGLTF_MODE_TRIANGLES;
        prim.material = cm.material;
        int pa = add_accessor(m, add_view(m, p.data(), p.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                              TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
        m.accessors[static_cast<size_t>(pa)].minValues.assign(lo, lo + 3);
        m.accessors[static_cast<size_t>(pa)].maxValues.assign(hi, hi + 3);
        prim.attributes["POSITION"] = pa;
        if (cm.normals) {
            n.resize(nv * 3);
            for (size_t v = 0; v < nv; v++) {
                const float *q = cm.normals + 3 * v;
                n[3 * v] = q[0];
                n[3 * v + 1] = q[2];
                n[3 * v + 2] = -q[1];
            }
            prim.attributes["NORMAL"] =
                add_accessor(m, add_view(m, n.data(), n.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
        }
        if (cm.uvs)
            prim.attributes["TEXCOORD_0"] =
                add_accessor(m, add_view(m, cm.uvs, nv * 2 * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, nv);
        size_t ni = static_cast<size_t>(cm.index_count);
        for (size_t k = 0; k < ni; k++)
            if (cm.indices[k] >= nv)
                return fail(path, err, err_size, CAT_ERR_INVALID,
                            "part %d: index %u out of range (%zu vertices)", i, cm.indices[k], nv);
        if (nv <= 65535) { // 16-bit indices halve the index data of every small part
            std::vector<unsigned short> s(cm.indices, cm.indices + ni);
            prim.indices =
                add_accessor(m, add_view(m, s.data(), ni * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, ni);
        } else {
            prim.indices = add_accessor(
                m, add_view(m, cm.indices, ni * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, ni);
        }
        tinygltf::Mesh mesh;
        mesh.name = cm.material >= 0 ? m.materials[static_cast<size_t>(cm.material)].name
                                     : "part " + std::to_string(i);
        mesh.primitives.push_back(prim);
        m.meshes.push_back(mesh);
        tinygltf::Node node;
        node.mesh = static_cast<int>(m.meshes.size() - 1);
        node.name = mesh.name;
        m.nodes.push_back(node);
        scene.nodes.push_back(static_cast<int>(m.nodes.size() - 1));
    }
    m.scenes.push_back(scene);
    m.defaultScene = 0;
    return CAT_OK;
}

bool keep_image(tinygltf::Image *image, const int, std::string *, std::string *, int, int,
                const unsigned char *, int, void *)
{
    image->as_is = true;
    return true;
}

bool no_file(const std::string &, void *)
{
    return false;
}
std::string same_path(const std::string &p, void *)
{
    return p;
}
bool no_read(std::vector<unsigned char> *, std::string *err, const std::string &, void *)
{
    if (err)
        *err = "external buffers are not read here";
    return false;
}
bool no_write(std::string *err, const std::string &, const std::vector<unsigned char> &, void *)
{
    if (err)
        *err = "writing files is disabled";
    return false;
}

float number(const tinygltf::Value &o, const char *key, float def)
{
    if (!o.Has(key) || !o.Get(key).IsNumber())
        return def;
    return static_cast<float>(o.Get(key).GetNumberAsDouble());
}

void read_rgb(const tinygltf::Value &o, const char *key, float out[3])
{
    if (!o.Has(key) || !o.Get(key).IsArray() || o.Get(key).ArrayLen() != 3)
        return;
    const tinygltf::Value &a = o.Get(key);
    for (int k = 0; k < 3; k++)
        if (a.Get(k).IsNumber())
            out[k] = static_cast<float>(a.Get(k).GetNumberAsDouble());
}

} // namespace

extern "C" void cat_material_from_render(const cat_render_material *r, const char *name,
                                         cat_material *out)
{
    std::memset(out, 0, sizeof *out);
    std::snprintf(out->name, sizeof out->name, "%s", name ? name : "");
    auto lum = [](const float c[3]) { return (c[0] + c[1] + c[2]) / 3.0f; };
    float metallic = (lum(r->specular) - lum(r->diffuse)) / 0.6f;
    metallic = std::min(1.0f, std::max(0.0f, metallic));
    for (int k = 0; k < 3; k++)
        out->base_color[k] = r->diffuse[k] + (r->specular[k] - r->diffuse[k]) * metallic;
    out->base_color[3] = std::min(1.0f, std::max(0.0f, 1.0f - r->transparency));
    out->metallic = metallic;
    out->roughness = std::min(1.0f, std::max(0.02f, 1.0f - r->glossiness));
    float e = std::max(r->emissive[0], std::max(r->emissive[1], r->emissive[2]));
    for (int k = 0; k < 3; k++)
        out->emissive[k] = e > 1.0f ? r->emissive[k] / e : std::max(0.0f, r->emissive[k]);
}

extern "C" cat_result cat_model_write_glb(const char *path, const cat_model *src,
                                          const cat_material_extras *extras, char *err,
                                          size_t err_size)
{
    if (err && err_size)
        err[0] = 0;
    if (!path || !*path)
        return fail("(no file)", err, err_size, CAT_ERR_INVALID, "no output path");
    if (!src || src->mesh_count <= 0 || !src->meshes)
        return fail(path, err, err_size, CAT_ERR_INVALID, "the model has no parts");
    try {
        tinygltf::Model m;
        cat_result r = build(path, src, extras, m, err, err_size);
        if (r != CAT_OK)
            return r;
        std::ostringstream out;
        tinygltf::TinyGLTF writer;
        if (!writer.WriteGltfSceneToStream(&m, out, false, true))
            return fail(path, err, err_size, CAT_ERR_INVALID, "tinygltf could not write it");
        return write_atomic(path, out.str(), err, err_size);
    } catch (const std::bad_alloc &) {
        return fail(path, err, err_size, CAT_ERR_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception &e) {
        return fail(path, err, err_size, CAT_ERR_INVALID, "%s", e.what());
    }
}

extern "C" cat_result cat_model_read_extras(const char *path, cat_material_extras *out, int max,
                                            int *count, char *err, size_t err_size)
{
    if (count)
        *count = 0;
    if (!path || !out || max < 0 || !count)
        return fail(path, err, err_size, CAT_ERR_INVALID, "bad arguments");
    try {
        // The loader's own checks first (size limit, GLB container, JSON depth and counts), so
        // that a hostile file is refused before tinygltf and its JSON parser see it.
        cat_msg msg = {path, err, err_size};
        unsigned char *raw = nullptr;
        size_t raw_size = 0;
        cat_result r =
            cat_read_file(&msg, "the file", path, CAT_MODEL_MAX_FILE_BYTES, &raw, &raw_size);
        if (r != CAT_OK)
            return r;
        std::vector<unsigned char> bytes(raw, raw + raw_size);
        std::free(raw);
        bool glb = bytes.size() >= 4 && !std::memcmp(bytes.data(), "glTF", 4);
        const unsigned char *json = bytes.data();
        size_t json_size = bytes.size();
        if (bytes.empty())
            return fail(path, err, err_size, CAT_ERR_PARSE, "not a glTF file (the file is empty)");
        if (glb &&
            (r = cat_glb_check(&msg, bytes.data(), bytes.size(), &json, &json_size)) != CAT_OK)
            return r;
        if ((r = cat_json_scan(&msg, json, json_size)) != CAT_OK)
            return r;
        tinygltf::Model m;
        tinygltf::TinyGLTF loader;
        loader.SetImageLoader(keep_image, nullptr);
        loader.SetFsCallbacks({no_file, same_path, no_read, no_write, nullptr});
        std::string e, w;
        bool ok = glb ? loader.LoadBinaryFromMemory(&m, &e, &w, bytes.data(),
                                                    static_cast<unsigned>(bytes.size()), "")
                      : loader.LoadASCIIFromString(&m, &e, &w,
                                                   reinterpret_cast<const char *>(bytes.data()),
                                                   static_cast<unsigned>(bytes.size()), "");
        if (!ok)
            return fail(path, err, err_size, CAT_ERR_INVALID, "%s", e.c_str());
        int n = 0;
        for (const tinygltf::Material &mat : m.materials) {
            if (n >= max)
                break;
            cat_material_extras &x = out[n++];
            std::memset(&x, 0, sizeof x);
            if (!mat.extras.IsObject() || !mat.extras.Has("tessera") ||
                !mat.extras.Get("tessera").IsObject())
                continue;
            const tinygltf::Value &t = mat.extras.Get("tessera");
            x.present = 1;
            read_rgb(t, "ambient", x.params.ambient);
            read_rgb(t, "diffuse", x.params.diffuse);
            read_rgb(t, "specular", x.params.specular);
            read_rgb(t, "emissive", x.params.emissive);
            x.params.shininess = number(t, "shininess", 0);
            x.params.reflectivity = number(t, "k_r", 0);
            x.params.glossiness = number(t, "g", 0);
            x.params.transparency = number(t, "transparency", 0);
            x.params.ior = number(t, "ior", 1);
            if (t.Has("blend") && t.Get("blend").IsString())
                cat_blend_parse(t.Get("blend").Get<std::string>().c_str(), &x.params.blend);
            x.variant_slot = t.Has("variant_slot") && t.Get("variant_slot").IsBool() &&
                             t.Get("variant_slot").Get<bool>();
        }
        *count = n;
        return CAT_OK;
    } catch (const std::bad_alloc &) {
        return fail(path, err, err_size, CAT_ERR_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception &ex) {
        return fail(path, err, err_size, CAT_ERR_INVALID, "%s", ex.what());
    }
}
