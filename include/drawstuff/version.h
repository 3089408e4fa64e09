/* SPDX-License-Identifier: BSD-3-Clause */
/* version.h -- the drawstuff API version (major in the high byte, minor in
 * the low byte), the value a program puts in dsFunctions.version. */
#ifndef DRAWSTUFF_VERSION_H
#define DRAWSTUFF_VERSION_H

#define DS_VERSION 0x0002

#endif
