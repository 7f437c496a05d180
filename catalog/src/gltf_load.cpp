// The C++ seam around tinygltf: parse, then copy the parse into the plain C cat_gltf_doc.
// No checks and no computation here (they are in model_*.c); every exception stops here.
//
// tinygltf is built in this file only, without stb: images are never decoded (an embedded
// image's bytes are accepted as they are, an external image is only named by its URI), and
// tinygltf reads no file itself: the buffer files it asks for are read by C code that refuses
// anything outside the model's folder.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <fstream> // tiny_gltf.h 2.7 uses std::ofstream but includes <fstream> only with its FS code
#include <tiny_gltf.h>

#include "model_internal.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace
{

struct holder {
    tinygltf::Model model;
    std::vector<cat_gltf_buffer> buffers;
    std::vector<cat_gltf_view> views;
    std::vector<cat_gltf_accessor> accessors;
    std::vector<std::vector<cat_gltf_attribute>> attributes; // per mesh primitive, flattened
    std::vector<std::vector<cat_gltf_primitive>> primitives; // per mesh
    std::vector<cat_gltf_mesh> meshes;
    std::vector<cat_gltf_node> nodes;
    std::vector<cat_gltf_scene> scenes;
    std::vector<cat_gltf_material> materials;
    std::vector<cat_gltf_texture> textures;
    std::vector<cat_gltf_image> images;
    std::vector<const char *> extensions_required;
};

bool keep_image_undecoded(tinygltf::Image *image, const int, std::string *, std::string *, int, int,
                          const unsigned char *, int, void *)
{
    image->as_is = true;
    return true;
}

bool file_exists(const std::string &, void *)
{
    return true; // existence is found out when C reads the file
}

std::string expand_file_path(const std::string &path, void *)
{
    return path;
}

bool read_whole_file(std::vector<unsigned char> *out, std::string *err, const std::string &uri,
                     void *user)
{
    cat_gltf_io *io = static_cast<cat_gltf_io *>(user);
    unsigned char *data = nullptr;
    size_t size = 0;
    if (cat_gltf_read_external(io, uri.c_str(), uri.size(), &data, &size) != CAT_OK) {
        if (err)
            *err = io->message;
        return false;
    }
    try {
        out->assign(data, data + size);
    } catch (...) {
        std::free(data);
        throw;
    }
    std::free(data);
    return true;
}

bool write_whole_file(std::string *err, const std::string &, const std::vector<unsigned char> &,
                      void *)
{
    if (err)
        *err = "writing files is disabled";
    return false;
}

template <typename T> const T *data_or_null(const std::vector<T> &v)
{
    return v.empty() ? nullptr : v.data();
}

void copy_doc(holder &h, cat_gltf_doc *doc)
{
    const tinygltf::Model &m = h.model;
    for (const tinygltf::Buffer &b : m.buffers)
        h.buffers.push_back({data_or_null(b.data), b.data.size()});
    for (const tinygltf::BufferView &v : m.bufferViews)
        h.views.push_back({v.buffer, v.byteOffset, v.byteLength, v.byteStride});
    for (const tinygltf::Accessor &a : m.accessors) {
        cat_gltf_accessor c{};
        c.view = a.bufferView;
        c.offset = a.byteOffset;
        c.component_type = a.componentType;
        c.normalized = a.normalized;
        c.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
        c.is_matrix = a.type == TINYGLTF_TYPE_MAT2 || a.type == TINYGLTF_TYPE_MAT3 ||
                      a.type == TINYGLTF_TYPE_MAT4;
        c.count = a.count;
        c.sparse = a.sparse.isSparse;
        c.sparse_count = a.sparse.count;
        c.sparse_indices_view = a.sparse.indices.bufferView;
        c.sparse_indices_offset = a.sparse.indices.byteOffset;
        c.sparse_indices_type = a.sparse.indices.componentType;
        c.sparse_values_view = a.sparse.values.bufferView;
        c.sparse_values_offset = a.sparse.values.byteOffset;
        h.accessors.push_back(c);
    }
    h.primitives.resize(m.meshes.size());
    for (size_t i = 0; i < m.meshes.size(); i++) {
        for (const tinygltf::Primitive &p : m.meshes[i].primitives) {
            h.attributes.emplace_back();
            std::vector<cat_gltf_attribute> &attrs = h.attributes.back();
            for (const auto &kv : p.attributes)
                attrs.push_back({kv.first.c_str(), kv.second});
            h.primitives[i].push_back({data_or_null(attrs), static_cast<int>(attrs.size()),
                                       p.indices, p.material, p.mode});
        }
        h.meshes.push_back(
            {data_or_null(h.primitives[i]), static_cast<int>(h.primitives[i].size())});
    }
    for (const tinygltf::Node &n : m.nodes)
        h.nodes.push_back({n.mesh, data_or_null(n.children), static_cast<int>(n.children.size()),
                           data_or_null(n.matrix), static_cast<int>(n.matrix.size()),
                           data_or_null(n.translation), static_cast<int>(n.translation.size()),
                           data_or_null(n.rotation), static_cast<int>(n.rotation.size()),
                           data_or_null(n.scale), static_cast<int>(n.scale.size())});
    for (const tinygltf::Scene &s : m.scenes)
        h.scenes.push_back({data_or_null(s.nodes), static_cast<int>(s.nodes.size())});
    for (const tinygltf::Material &mat : m.materials) {
        const tinygltf::PbrMetallicRoughness &pbr = mat.pbrMetallicRoughness;
        h.materials.push_back({mat.name.c_str(), data_or_null(pbr.baseColorFactor),
                               static_cast<int>(pbr.baseColorFactor.size()), pbr.metallicFactor,
                               pbr.roughnessFactor, data_or_null(mat.emissiveFactor),
                               static_cast<int>(mat.emissiveFactor.size()),
                               pbr.baseColorTexture.index});
    }
    for (const tinygltf::Texture &t : m.textures)
        h.textures.push_back({t.source});
    for (const tinygltf::Image &img : m.images)
        h.images.push_back({img.uri.c_str()});
    for (const std::string &e : m.extensionsRequired)
        h.extensions_required.push_back(e.c_str());

    doc->buffers = data_or_null(h.buffers);
    doc->buffer_count = static_cast<int>(h.buffers.size());
    doc->views = data_or_null(h.views);
    doc->view_count = static_cast<int>(h.views.size());
    doc->accessors = data_or_null(h.accessors);
    doc->accessor_count = static_cast<int>(h.accessors.size());
    doc->meshes = data_or_null(h.meshes);
    doc->mesh_count = static_cast<int>(h.meshes.size());
    doc->nodes = data_or_null(h.nodes);
    doc->node_count = static_cast<int>(h.nodes.size());
    doc->scenes = data_or_null(h.scenes);
    doc->scene_count = static_cast<int>(h.scenes.size());
    doc->default_scene = m.defaultScene;
    doc->materials = data_or_null(h.materials);
    doc->material_count = static_cast<int>(h.materials.size());
    doc->textures = data_or_null(h.textures);
    doc->texture_count = static_cast<int>(h.textures.size());
    doc->images = data_or_null(h.images);
    doc->image_count = static_cast<int>(h.images.size());
    doc->extensions_required = data_or_null(h.extensions_required);
    doc->extensions_required_count = static_cast<int>(h.extensions_required.size());
}

void put_detail(char *detail, size_t size, const char *text)
{
    if (detail && size)
        std::snprintf(detail, size, "%s", text);
}

} // namespace

extern "C" cat_result cat_gltf_parse(const unsigned char *bytes, size_t size, int is_glb,
                                     cat_gltf_io *io, cat_gltf_doc *doc, void **handle,
                                     char *detail, size_t detail_size)
{
    *handle = nullptr;
    put_detail(detail, detail_size, "");
    holder *h = nullptr;
    try {
        h = new holder;
        *handle = h;
        tinygltf::TinyGLTF loader;
        loader.SetImageLoader(keep_image_undecoded, nullptr);
        loader.SetFsCallbacks(
            {file_exists, expand_file_path, read_whole_file, write_whole_file, io});
        std::string err, warn;
        // base_dir "": buffer URIs reach read_whole_file as they are in the file (decoded),
        // and C resolves them against the model's folder.
        bool ok = is_glb ? loader.LoadBinaryFromMemory(&h->model, &err, &warn, bytes,
                                                       static_cast<unsigned int>(size), "")
                         : loader.LoadASCIIFromString(&h->model, &err, &warn,
                                                      reinterpret_cast<const char *>(bytes),
                                                      static_cast<unsigned int>(size), "");
        if (!ok) {
            put_detail(detail, detail_size, err.empty() ? "tinygltf gave no reason" : err.c_str());
            return CAT_ERR_INVALID;
        }
        copy_doc(*h, doc);
        return CAT_OK;
    } catch (const std::bad_alloc &) {
        put_detail(detail, detail_size, "out of memory in tinygltf");
        return CAT_ERR_OUT_OF_MEMORY;
    } catch (const std::exception &e) {
        put_detail(detail, detail_size, e.what());
        return CAT_ERR_INVALID;
    } catch (...) {
        put_detail(detail, detail_size, "unknown C++ exception in tinygltf");
        return CAT_ERR_INVALID;
    }
}

extern "C" void cat_gltf_release(void *handle)
{
    delete static_cast<holder *>(handle);
}
