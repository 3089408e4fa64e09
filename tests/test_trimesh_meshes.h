// SPDX-License-Identifier: BSD-3-Clause
//
// test_trimesh_meshes.h -- meshes generated for the trimesh tests (no model
// files): a grid terrain, an icosphere, a closed box, a torus and a thin
// sheet, all wound outwards (counter-clockwise seen from outside), with the
// signed distance of the solid each stands for (positive inside).

#ifndef TEST_TRIMESH_MESHES_H
#define TEST_TRIMESH_MESHES_H

#include <ode/ode.h>

typedef struct test_mesh {
    double (*v)[3];          // vertices
    dTriIndex (*tri)[3];     // triangles
    int nv, nt;
    dTriMeshDataID data;     // built with dGeomTriMeshDataBuildDouble
} test_mesh;

// An n x n-cell grid over [-half, half]^2 at height z = height(x, y) (NULL:
// flat at 0), triangles facing up; the solid is below.
void mesh_grid(test_mesh *m, int n, double half, double (*height)(double x, double y));
// A sphere of radius r: an icosahedron subdivided `levels` times, pushed out
// to the sphere (vertices on the sphere, centre at the origin).
void mesh_icosphere(test_mesh *m, double r, int levels);
// A closed box with full sides lx, ly, lz centred at the origin, each face a
// grid of n x n cells.
void mesh_box(test_mesh *m, double lx, double ly, double lz, int n);
// A torus about the z axis: tube radius r at distance R from the axis,
// nu x nv quads.
void mesh_torus(test_mesh *m, double R, double r, int nu, int nv);
// A one-sided sheet: the grid's [-half, half]^2 square at z = 0 made of two
// triangles.
void mesh_sheet(test_mesh *m, double half);
void mesh_free(test_mesh *m);

// Signed distances (positive inside) of the solids, in the mesh frame.
double sdf_sphere(double r, const double p[3]);
double sdf_box(double lx, double ly, double lz, const double p[3]);
double sdf_torus(double R, double r, const double p[3]);

#endif
