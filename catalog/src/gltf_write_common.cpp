// The shared parts of GLB writing (gltf_write_common.h).
#include "gltf_write_common.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace cat_gltf
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

namespace
{

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
        return fail(path, err, err_size, CAT_ERR_IO,
                    "cannot write: cannot create a temporary file: %s", std::strerror(errno));
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
        return fail(path, err, err_size, CAT_ERR_IO,
                    "cannot write: cannot rename the temporary file: %s", std::strerror(e));
    }
    return CAT_OK;
}

} // namespace

void add_materials(tinygltf::Model &m, const cat_material *materials, int count,
                   const cat_material_extras *extras)
{
    for (int i = 0; i < count; i++) {
        const cat_material &cm = materials[i];
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
}

cat_result add_part_positions(const char *path, const char *part, const cat_mesh &cm,
                              int material_count, tinygltf::Model &m, tinygltf::Primitive &prim,
                              char *err, size_t err_size)
{
    if (!cm.positions || !cm.indices || cm.vertex_count <= 0 || cm.index_count <= 0 ||
        cm.index_count % 3)
        return fail(path, err, err_size, CAT_ERR_INVALID, "%s: no triangles or no positions", part);
    if (cm.material < -1 || cm.material >= material_count)
        return fail(path, err, err_size, CAT_ERR_INVALID, "%s: material %d out of range", part,
                    cm.material);
    size_t nv = static_cast<size_t>(cm.vertex_count);
    // Z-up millimetres to glTF's Y-up metres: (x, y, z) -> (x, z, -y) / 1000.
    std::vector<float> p(nv * 3);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t v = 0; v < nv; v++) {
        const float *q = cm.positions + 3 * v;
        float g[3] = {q[0] / 1000.0f, q[2] / 1000.0f, -q[1] / 1000.0f};
        for (int k = 0; k < 3; k++) {
            if (!std::isfinite(g[k]))
                return fail(path, err, err_size, CAT_ERR_INVALID, "%s: vertex %zu is not finite",
                            part, v);
            p[3 * v + k] = g[k];
            lo[k] = std::min(lo[k], static_cast<double>(g[k]));
            hi[k] = std::max(hi[k], static_cast<double>(g[k]));
        }
    }
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = cm.material;
    int pa = add_accessor(m, add_view(m, p.data(), p.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                          TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
    m.accessors[static_cast<size_t>(pa)].minValues.assign(lo, lo + 3);
    m.accessors[static_cast<size_t>(pa)].maxValues.assign(hi, hi + 3);
    prim.attributes["POSITION"] = pa;
    return CAT_OK;
}

cat_result add_part_indices(const char *path, const char *part, const cat_mesh &cm,
                            tinygltf::Model &m, tinygltf::Primitive &prim, char *err,
                            size_t err_size)
{
    size_t nv = static_cast<size_t>(cm.vertex_count), ni = static_cast<size_t>(cm.index_count);
    for (size_t k = 0; k < ni; k++)
        if (cm.indices[k] >= nv)
            return fail(path, err, err_size, CAT_ERR_INVALID,
                        "%s: index %u out of range (%zu vertices)", part, cm.indices[k], nv);
    if (nv <= 65535) { // 16-bit indices halve the index data of every small part
        std::vector<unsigned short> s(cm.indices, cm.indices + ni);
        prim.indices =
            add_accessor(m, add_view(m, s.data(), ni * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, ni);
    } else {
        prim.indices =
            add_accessor(m, add_view(m, cm.indices, ni * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, ni);
    }
    return CAT_OK;
}

cat_result write_glb(const char *path, tinygltf::Model &m, char *err, size_t err_size)
{
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&m, out, false, true))
        return fail(path, err, err_size, CAT_ERR_INVALID, "tinygltf could not write it");
    return write_atomic(path, out.str(), err, err_size);
}

} // namespace cat_gltf
