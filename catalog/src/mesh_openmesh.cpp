// Thin C++ adapter: OpenMesh's quadric decimater behind the plain C call of mesh_internal.h.
// Every check happens in C (mesh_validate.c); this file only builds the half-edge mesh, runs
// DecimaterT with ModQuadric (Garland and Heckbert 1997) and ModNormalFlipping, and reads the
// surviving faces back. No exception leaves it.
#include "mesh_internal.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <vector>

namespace
{

typedef OpenMesh::TriMesh_ArrayKernelT<> Mesh;
typedef OpenMesh::Decimater::DecimaterT<Mesh> Decimater;
typedef OpenMesh::Decimater::ModQuadricT<Mesh>::Handle QuadricHandle;
typedef OpenMesh::Decimater::ModNormalFlippingT<Mesh>::Handle FlipHandle;

int decimate(const float *positions, int vertex_count, const unsigned *triangles,
             int triangle_count, int target_triangles, cat_decimate_result *out)
{
    Mesh mesh;
    // add_face reports complex edges on omerr(); we count them instead.
    omerr().disable();
    std::vector<Mesh::VertexHandle> vh((size_t)vertex_count);
    for (int v = 0; v < vertex_count; v++)
        vh[(size_t)v] = mesh.add_vertex(Mesh::Point(
            positions[3 * (size_t)v], positions[3 * (size_t)v + 1], positions[3 * (size_t)v + 2]));
    std::vector<unsigned> refused;
    for (int t = 0; t < triangle_count; t++) {
        const unsigned *c = triangles + 3 * (size_t)t;
        Mesh::FaceHandle f = mesh.add_face(vh[c[0]], vh[c[1]], vh[c[2]]);
        if (!f.is_valid())
            refused.insert(refused.end(), c, c + 3);
    }
    omerr().enable();

    mesh.request_vertex_status();
    mesh.request_edge_status();
    mesh.request_face_status();
    mesh.request_face_normals();
    mesh.update_face_normals();
    // Open edges keep their outline: a collapse along a boundary would pull a sheet's edge in.
    // Vertices on the bounding box stay too, so the box is kept exactly: a product's size is
    // what its catalog row says, at every level of detail.
    Mesh::Point lo(positions[0], positions[1], positions[2]), hi = lo;
    for (Mesh::VertexIter v = mesh.vertices_begin(); v != mesh.vertices_end(); ++v) {
        lo.minimize(mesh.point(*v));
        hi.maximize(mesh.point(*v));
    }
    for (Mesh::VertexIter v = mesh.vertices_begin(); v != mesh.vertices_end(); ++v) {
        const Mesh::Point &p = mesh.point(*v);
        bool on_box = false;
        for (int k = 0; k < 3; k++)
            on_box = on_box || p[k] == lo[k] || p[k] == hi[k];
        if (mesh.is_boundary(*v) || on_box)
            mesh.status(*v).set_locked(true);
    }

    Decimater dec(mesh);
    QuadricHandle quadric;
    FlipHandle flip;
    dec.add(quadric);
    dec.add(flip);
    dec.module(flip).set_max_normal_deviation(60.0f); // no face turns more than 60 degrees
    if (!dec.initialize())
        return 1;
    // The refused triangles pass through, so they count towards the target.
    int refused_count = (int)(refused.size() / 3);
    int target = target_triangles > refused_count + 1 ? target_triangles - refused_count : 1;
    if (target < (int)mesh.n_faces())
        dec.decimate_to_faces(0, (size_t)target);

    std::vector<unsigned> result;
    result.reserve(3 * (size_t)target_triangles + refused.size());
    for (Mesh::FaceIter f = mesh.faces_begin(); f != mesh.faces_end(); ++f) {
        if (mesh.status(*f).deleted())
            continue;
        for (Mesh::FaceVertexIter fv = mesh.fv_iter(*f); fv.is_valid(); ++fv)
            result.push_back((unsigned)fv->idx()); // no garbage collection: input numbering
    }
    result.insert(result.end(), refused.begin(), refused.end());
    out->triangles = (unsigned *)malloc(result.size() * sizeof(unsigned) + 1);
    if (!out->triangles)
        throw std::bad_alloc();
    std::copy(result.begin(), result.end(), out->triangles);
    out->triangle_count = (int)(result.size() / 3);
    out->refused = (int)(refused.size() / 3);
    return 0;
}

} // namespace

extern "C" int cat_openmesh_decimate(const float *positions, int vertex_count,
                                     const unsigned *triangles, int triangle_count,
                                     int target_triangles, cat_decimate_result *out, char *what,
                                     size_t what_size)
{
    out->triangles = nullptr;
    out->triangle_count = 0;
    out->refused = 0;
    try {
        if (decimate(positions, vertex_count, triangles, triangle_count, target_triangles, out)) {
            std::snprintf(what, what_size, "OpenMesh's decimater could not start");
            return 1;
        }
        return 0;
    } catch (const std::bad_alloc &) {
        std::snprintf(what, what_size, "out of memory in OpenMesh");
    } catch (const std::exception &e) {
        std::snprintf(what, what_size, "OpenMesh: %s", e.what());
    } catch (...) {
        std::snprintf(what, what_size, "OpenMesh failed");
    }
    free(out->triangles);
    out->triangles = nullptr;
    out->triangle_count = 0;
    return 1;
}
