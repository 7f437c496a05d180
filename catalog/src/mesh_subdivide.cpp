// The C++ seam around OpenMesh's uniform Catmull-Clark subdivider: a coarse polygon cage in,
// a smooth triangle mesh out (gen_internal.h, cat_mesh_subdivide). Ceramic shapes (basins,
// WC bowls, baths, trays) are modelled as cages of a few quads and smoothed here, as the
// subdivision-surface literature does (Catmull and Clark 1978). Every exception stops here.
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>

#include "gen_internal.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <vector>

namespace
{
typedef OpenMesh::PolyMesh_ArrayKernelT<> Mesh;

void put(char *err, size_t size, const char *text)
{
    if (err && size)
        std::snprintf(err, size, "mesh subdivision: %s", text);
}
} // namespace

extern "C" int cat_mesh_subdivide(const double *pos, int nv, const int *fstart, const int *fidx,
                                  int nf, int iterations, double **out_pos, int *out_nv,
                                  int **out_tri, int *out_nt, char *err, size_t err_size)
{
    *out_pos = nullptr;
    *out_tri = nullptr;
    *out_nv = *out_nt = 0;
    try {
        Mesh mesh;
        std::vector<Mesh::VertexHandle> vh;
        vh.reserve(static_cast<size_t>(nv));
        for (int v = 0; v < nv; v++)
            vh.push_back(mesh.add_vertex(Mesh::Point(static_cast<float>(pos[3 * v]),
                                                     static_cast<float>(pos[3 * v + 1]),
                                                     static_cast<float>(pos[3 * v + 2]))));
        std::vector<Mesh::VertexHandle> face;
        for (int f = 0; f < nf; f++) {
            face.clear();
            for (int k = fstart[f]; k < fstart[f + 1]; k++) {
                if (fidx[k] < 0 || fidx[k] >= nv) {
                    put(err, err_size, "face index out of range");
                    return 0;
                }
                face.push_back(vh[static_cast<size_t>(fidx[k])]);
            }
            if (!mesh.add_face(face).is_valid()) {
                put(err, err_size, "the cage is not a manifold polygon mesh");
                return 0;
            }
        }
        OpenMesh::Subdivider::Uniform::CatmullClarkT<Mesh> cc;
        cc.attach(mesh);
        cc(static_cast<size_t>(iterations));
        cc.detach();
        mesh.garbage_collection();
        size_t tris = 0;
        for (const auto &f : mesh.faces())
            tris += mesh.valence(f) - 2;
        double *p = static_cast<double *>(std::malloc(mesh.n_vertices() * 3 * sizeof(double) + 1));
        int *t = static_cast<int *>(std::malloc(tris * 3 * sizeof(int) + 1));
        if (!p || !t) {
            std::free(p);
            std::free(t);
            put(err, err_size, "out of memory");
            return 0;
        }
        for (const auto &v : mesh.vertices()) {
            const Mesh::Point &q = mesh.point(v);
            for (int k = 0; k < 3; k++)
                p[3 * v.idx() + k] = q[k];
        }
        size_t n = 0;
        for (const auto &f : mesh.faces()) {
            std::vector<int> ids;
            for (const auto &v : mesh.fv_range(f))
                ids.push_back(v.idx());
            for (size_t k = 1; k + 1 < ids.size(); k++) {
                t[3 * n] = ids[0];
                t[3 * n + 1] = ids[k];
                t[3 * n + 2] = ids[k + 1];
                n++;
            }
        }
        *out_pos = p;
        *out_tri = t;
        *out_nv = static_cast<int>(mesh.n_vertices());
        *out_nt = static_cast<int>(n);
        return 1;
    } catch (const std::bad_alloc &) {
        put(err, err_size, "out of memory");
    } catch (const std::exception &e) {
        put(err, err_size, e.what());
    } catch (...) {
        put(err, err_size, "unknown C++ exception");
    }
    return 0;
}
