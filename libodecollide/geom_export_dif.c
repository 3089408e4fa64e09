// SPDX-License-Identifier: BSD-3-Clause
//
// geom_export_dif.c -- the geom lines of dWorldExportDIF: category and
// collide bits when not all set, `disabled`, and the class with its sizes,
// as ODE writes them. Classes ODE writes no type for (geometry transforms,
// user classes) get the bits only. dGeomSetBody registers this writer with
// the dynamics library the first time a geom is attached to a body.

#include "geom_internal.h"

#include "../libodedyn/io/dif_print.h"

static void write_geom(const dxDifPrinter *p, dGeomID g)
{
    if (g->category_bits != ~0ul) {
        dxDifIndent(p);
        fprintf(p->file, "category_bits = %lu\n", g->category_bits);
    }
    if (g->collide_bits != ~0ul) {
        dxDifIndent(p);
        fprintf(p->file, "collide_bits = %lu\n", g->collide_bits);
    }
    if (!dGeomIsEnabled(g)) dxDifPrintInt(p, "disabled", 1);
    dVector4 v;
    dReal radius, length;
    switch (g->ops->cls) {
    case dSphereClass:
        dxDifPrintString(p, "type", "sphere");
        dxDifPrintReal(p, "radius", dGeomSphereGetRadius(g));
        break;
    case dBoxClass:
        dGeomBoxGetLengths(g, v);
        dxDifPrintString(p, "type", "box");
        dxDifPrintReals(p, "sides", v, 3);
        break;
    case dCapsuleClass:
    case dCylinderClass:
        if (g->ops->cls == dCapsuleClass) dGeomCapsuleGetParams(g, &radius, &length);
        else dGeomCylinderGetParams(g, &radius, &length);
        dxDifPrintString(p, "type", g->ops->cls == dCapsuleClass ? "capsule" : "cylinder");
        dxDifPrintReal(p, "radius", radius);
        dxDifPrintReal(p, "length", length);
        break;
    case dPlaneClass:
        dGeomPlaneGetParams(g, v);
        dxDifPrintString(p, "type", "plane");
        dxDifPrintReals(p, "normal", v, 3);
        dxDifPrintReal(p, "d", v[3]);
        break;
    case dRayClass:
        dxDifPrintString(p, "type", "ray");
        dxDifPrintReal(p, "length", dGeomRayGetLength(g));
        break;
    default:
        break;
    }
}

void dxGeomRegisterDifWriter(void)
{
    dxDifSetGeomWriter(write_geom);
}
