/* SPDX-License-Identifier: BSD-3-Clause */
/* version.h -- the ODE API version this library implements. */
#ifndef ODE_VERSION_H
#define ODE_VERSION_H

#define dODE_VERSION "0.16.2"

#endif
