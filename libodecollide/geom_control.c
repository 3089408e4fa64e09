// SPDX-License-Identifier: BSD-3-Clause
//
// geom_control.c -- dGeomLowLevelControl (ODE 0.16): class-specific settings
// by control class and code. A geometry class that has codes registers its
// handler with dxGeomRegisterControl (ODE's triangle mesh has the
// merge-sphere-contacts codes of the collider class; the classes here have
// none yet). For a class without a handler the call is reported, as ODE
// reports it, and fails with *dataSize 0.

#include "geom_internal.h"

static dxGeomControlFn *handlers[dGeomNumClasses];

void dxGeomRegisterControl(int cls, dxGeomControlFn *fn)
{
    if (cls >= 0 && cls < dGeomNumClasses) handlers[cls] = fn;
}

int dxGeomControlSizeValid(const void *dataValue, int *dataSize, int required)
{
    if (*dataSize == required && (required == 0 || dataValue != NULL)) return 1;
    *dataSize = required;
    return 0;
}

int dGeomLowLevelControl(dGeomID g, int controlClass, int controlCode, void *dataValue,
                         int *dataSize)
{
    DX_CHECK_GEOM(g, return 0);
    DX_CHECK_ARG(dataSize != NULL, return 0, "dataSize is NULL");
    dxGeomControlFn *fn = handlers[g->ops->cls];
    if (!fn) *dataSize = 0;
    DX_CHECK_ARG(fn != NULL, return 0, "a %s has no control codes (class %d, code %d)",
                 g->ops->name, controlClass, controlCode);
    return fn(g, controlClass, controlCode, dataValue, dataSize);
}
