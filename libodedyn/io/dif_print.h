// SPDX-License-Identifier: BSD-3-Clause
//
// dif_print.h -- how DIF text (dWorldExportDIF) is printed: one `name = value,`
// per line, tab-indented, reals with %.*g (15 digits, 7 with dSINGLE), "inf"
// and "-inf" for the infinities. Shared by the dynamics library's exporter
// and the collision library's geom writer, so both print numbers alike.
// Also the one link between them for DIF: the collision library registers
// its geom writer here (dxDifSetGeomWriter) when it first attaches a geom to
// a body, so libodedyn needs no collision symbol to describe geoms.

#ifndef DX_DIF_PRINT_H
#define DX_DIF_PRINT_H

#include <ode/common.h>
#include <stdio.h>

typedef struct dxDifPrinter {
    FILE *file;
    int precision;   // significant digits of reals
    int indent;      // tabs before each line
} dxDifPrinter;

static inline void dxDifIndent(const dxDifPrinter *p)
{
    for (int i = 0; i < p->indent; i++) fputc('\t', p->file);
}

static inline void dxDifReal(const dxDifPrinter *p, dReal x)
{
    if (x == dInfinity) fputs("inf", p->file);
    else if (x == -dInfinity) fputs("-inf", p->file);
    else fprintf(p->file, "%.*g", p->precision, (double)x);
}

// `name = x,`
static inline void dxDifPrintReal(const dxDifPrinter *p, const char *name, dReal x)
{
    dxDifIndent(p);
    fprintf(p->file, "%s = ", name);
    dxDifReal(p, x);
    fputs(",\n", p->file);
}

// `name = {x0,x1,...},` with n components
static inline void dxDifPrintReals(const dxDifPrinter *p, const char *name, const dReal *x, int n)
{
    dxDifIndent(p);
    fprintf(p->file, "%s = {", name);
    for (int i = 0; i < n; i++) {
        dxDifReal(p, x[i]);
        if (i < n - 1) fputc(',', p->file);
    }
    fputs("},\n", p->file);
}

static inline void dxDifPrintInt(const dxDifPrinter *p, const char *name, int x)
{
    dxDifIndent(p);
    fprintf(p->file, "%s = %d,\n", name, x);
}

// `name = "text",`
static inline void dxDifPrintString(const dxDifPrinter *p, const char *name, const char *text)
{
    dxDifIndent(p);
    fprintf(p->file, "%s = \"%s\",\n", name, text);
}

// A line as it is (an opening or closing brace, `ODE = {`, ...).
static inline void dxDifPrintLine(const dxDifPrinter *p, const char *line)
{
    dxDifIndent(p);
    fprintf(p->file, "%s\n", line);
}

// Writes the lines that describe geom g (its class, size and bits).
typedef void dxDifGeomWriter(const dxDifPrinter *p, dGeomID g);

#if defined(__GNUC__)
#define DX_DIF_EXPORT __attribute__((visibility("default")))
#else
#define DX_DIF_EXPORT
#endif

// Called by the collision library (exported from libodedyn for it, not part
// of the public API). Without a writer, bodies are written without geoms.
DX_DIF_EXPORT void dxDifSetGeomWriter(dxDifGeomWriter *writer);

#endif
