// SPDX-License-Identifier: BSD-3-Clause
//
// diff_print.h -- output of the differential test programs. Each line is
//   name tolerance value value ...
// and compare.py checks that two builds print the same names and values
// within the line's absolute tolerance. Only the ODE API is used here, so the
// same source builds against this library and against the reference ODE.

#ifndef DIFF_PRINT_H
#define DIFF_PRINT_H

#include <ode/ode.h>
#include <stdio.h>

static inline void diff_values(const char *name, double tol, const dReal *v, int n)
{
    printf("%s %.3g", name, tol);
    for (int i = 0; i < n; i++) printf(" %.17g", (double)v[i]);
    printf("\n");
}

static inline void diff_value(const char *name, double tol, double v)
{
    printf("%s %.3g %.17g\n", name, tol, v);
}

// A dMatrix3 without its unused fourth column.
static inline void diff_matrix3(const char *name, double tol, const dMatrix3 R)
{
    dReal v[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) v[i * 3 + j] = R[i * 4 + j];
    diff_values(name, tol, v, 9);
}

#endif
