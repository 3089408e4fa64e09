/* SPDX-License-Identifier: BSD-3-Clause */
/* compatibility.h -- the ODE 0.5 names of functions that later ODE renamed or
 * whose argument order changed. */
#ifndef ODE_COMPATIBILITY_H
#define ODE_COMPATIBILITY_H

/* 0.5: dQtoR(q, R), dRtoQ(R, q), dWtoDQ(w, q, dq); 0.16 puts the output first. */
#define dQtoR(q, R) dRfromQ((R), (q))
#define dRtoQ(R, q) dQfromR((q), (R))
#define dWtoDQ(w, q, dq) dDQfromW((dq), (w), (q))

#endif
