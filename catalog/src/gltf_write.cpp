// Writing models as GLB with tinygltf (catalog/model_write.h), and reading back the Tessera
// extras of a file's materials. The helpers shared with the scene writer are in
// gltf_write_common.h.
#include "gltf_write_common.h"
#include "model_internal.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using cat_gltf::add_accessor;
using cat_gltf::add_view;
using cat_gltf::fail;

namespace
{

cat_result build(const char *path, const cat_model *src, const cat_material_extras *extras,
                 tinygltf::Model &m, char *err, size_t err_size)
{
    m.asset.version = "2.0";
    m.asset.generator = "Tessera model writer";
    m.buffers.resize(1);
    cat_gltf::add_materials(m, src->materials, src->material_count, extras);
    tinygltf::Scene scene;
    for (int i = 0; i < src->mesh_count; i++) {
        const cat_mesh &cm = src->meshes[i];
        std::string part = "part " + std::to_string(i);
        tinygltf::Primitive prim;
        cat_result r = cat_gltf::add_part_positions(path, part.c_str(), cm, src->material_count, m,
                                                    prim, err, err_size);
        if (r != CAT_OK)
            return r;
        size_t nv = static_cast<size_t>(cm.vertex_count);
        std::vector<float> n;
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
        r = cat_gltf::add_part_indices(path, part.c_str(), cm, m, prim, err, err_size);
        if (r != CAT_OK)
            return r;
        tinygltf::Mesh mesh;
        mesh.name = cm.material >= 0 ? m.materials[static_cast<size_t>(cm.material)].name : part;
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
    return cat_gltf::guarded(path, err, err_size, [&] {
        tinygltf::Model m;
        cat_result r = build(path, src, extras, m, err, err_size);
        return r == CAT_OK ? cat_gltf::write_glb(path, m, err, err_size) : r;
    });
}

extern "C" cat_result cat_model_read_extras(const char *path, cat_material_extras *out, int max,
                                            int *count, char *err, size_t err_size)
{
    if (count)
        *count = 0;
    if (!path || !out || max < 0 || !count)
        return fail(path, err, err_size, CAT_ERR_INVALID, "bad arguments");
    return cat_gltf::guarded(path, err, err_size, [&]() -> cat_result {
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
    });
}
