// What the model writer (gltf_write.cpp) and the scene writer (gltf_write_scene.cpp) share:
// messages, buffer views and accessors, materials with Tessera's extras, a part's positions
// and indices, and the GLB written atomically. tinygltf's implementation is compiled once, in
// gltf_load.cpp, with the same configuration macros as below; the writers only use its
// classes. C++: included by the tinygltf adapters only.
#ifndef CATALOG_GLTF_WRITE_COMMON_H
#define CATALOG_GLTF_WRITE_COMMON_H

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <fstream> // tiny_gltf.h 2.7 uses std::ofstream but includes <fstream> only with its FS code
#include <tiny_gltf.h>

#include "catalog/model.h"
#include "catalog/model_write.h"

#include <cstddef>
#include <exception>
#include <new>

namespace cat_gltf
{

// "path: message" into err (when given); returns code.
cat_result fail(const char *path, char *err, size_t size, cat_result code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

// Appends bytes to the single buffer, 4-byte aligned, and returns a new buffer view's index.
int add_view(tinygltf::Model &m, const void *data, size_t bytes, int target);
int add_accessor(tinygltf::Model &m, int view, int component, int type, size_t count);
// The materials, with Tessera's extras ({"tessera": {...}}, read by cat_model_read_extras)
// where extras[i].present; extras may be NULL.
void add_materials(tinygltf::Model &m, const cat_material *materials, int count,
                   const cat_material_extras *extras);
// A part checked (triangles, positions, a material below material_count) and its positions,
// from Z-up millimetres to glTF's Y-up metres, as its POSITION (with bounds). `part` names it
// in messages ("part 2").
cat_result add_part_positions(const char *path, const char *part, const cat_mesh &cm,
                              int material_count, tinygltf::Model &m, tinygltf::Primitive &prim,
                              char *err, size_t err_size);
// The part's indices checked and added, 16-bit when its vertices allow.
cat_result add_part_indices(const char *path, const char *part, const cat_mesh &cm,
                            tinygltf::Model &m, tinygltf::Primitive &prim, char *err,
                            size_t err_size);
// The model as GLB bytes written through a temporary file in the same folder (fsync, rename),
// so a reader sees the old file or the whole new one.
cat_result write_glb(const char *path, tinygltf::Model &m, char *err, size_t err_size);

// build() with tinygltf's exceptions as messages.
template <class Build> cat_result guarded(const char *path, char *err, size_t err_size, Build build)
{
    try {
        return build();
    } catch (const std::bad_alloc &) {
        return fail(path, err, err_size, CAT_ERR_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception &e) {
        return fail(path, err, err_size, CAT_ERR_INVALID, "%s", e.what());
    }
}

} // namespace cat_gltf

#endif
