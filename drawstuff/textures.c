// SPDX-License-Identifier: BSD-3-Clause
//
// textures.c -- the four textures (wood, checkered, ground, sky), generated
// here from tileable value noise: no image files. Each repeats seamlessly.

#include "ds_internal.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#define TEXTURE_SIZE 128

static GLuint names[DS_SKY + 1];

// A pseudo-random value in [0, 1) for lattice point (x, y) of a layer.
static float lattice(uint32_t x, uint32_t y, uint32_t layer)
{
    uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ layer * 0xcb1ab31fu;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return (float)(h & 0xffffffu) / 16777216.0f;
}

// Value noise with `cells` lattice cells across the unit square, wrapping at
// its edges; u, v in [0, 1). Smoothstep interpolation between lattice values.
static float noise(float u, float v, int cells, uint32_t layer)
{
    float x = u * (float)cells, y = v * (float)cells;
    int x0 = (int)floorf(x), y0 = (int)floorf(y);
    float fx = x - (float)x0, fy = y - (float)y0;
    fx = fx * fx * (3.0f - 2.0f * fx);
    fy = fy * fy * (3.0f - 2.0f * fy);
    uint32_t xa = (uint32_t)(x0 % cells), xb = (uint32_t)((x0 + 1) % cells);
    uint32_t ya = (uint32_t)(y0 % cells), yb = (uint32_t)((y0 + 1) % cells);
    float a = lattice(xa, ya, layer) + fx * (lattice(xb, ya, layer) - lattice(xa, ya, layer));
    float b = lattice(xa, yb, layer) + fx * (lattice(xb, yb, layer) - lattice(xa, yb, layer));
    return a + fy * (b - a);
}

// Fractal noise: octaves from `cells` cells up, each half as strong; in [0, 1).
static float fractal(float u, float v, int cells, int octaves, uint32_t layer)
{
    float sum = 0.0f, weight = 1.0f, total = 0.0f;
    for (int i = 0; i < octaves; i++) {
        sum += weight * noise(u, v, cells << i, layer + (uint32_t)i);
        total += weight;
        weight *= 0.5f;
    }
    return sum / total;
}

static unsigned char byte(float c)
{
    c = c < 0.0f ? 0.0f : c > 1.0f ? 1.0f : c;
    return (unsigned char)(c * 255.0f + 0.5f);
}

static void mix(unsigned char *out, const float a[3], const float b[3], float t)
{
    for (int i = 0; i < 3; i++) out[i] = byte(a[i] + t * (b[i] - a[i]));
}

// Earth: a fine sandy grain over faint patches, so the metre-sized tiles
// do not show as a pattern.
static void ground_texel(float u, float v, unsigned char *out)
{
    static const float dark[3] = { 0.44f, 0.42f, 0.30f }, light[3] = { 0.60f, 0.56f, 0.40f };
    float t = 0.5f + 0.5f * (fractal(u, v, 16, 3, 1) - 0.5f) + 0.9f * (noise(u, v, 64, 9) - 0.5f);
    mix(out, dark, light, t);
}

// Blue sky with soft white clouds where the noise is high.
static void sky_texel(float u, float v, unsigned char *out)
{
    static const float blue[3] = { 0.28f, 0.50f, 0.92f }, white[3] = { 0.95f, 0.96f, 1.0f };
    float t = fractal(u, v, 4, 5, 20);
    t = (t - 0.5f) * 3.0f;
    mix(out, blue, white, t < 0.0f ? 0.0f : t);
}

// Wood: rings around the tile's centre, wobbled by noise.
static void wood_texel(float u, float v, unsigned char *out)
{
    static const float early[3] = { 0.95f, 0.86f, 0.68f }, late[3] = { 0.72f, 0.58f, 0.40f };
    float du = u - 0.5f, dv = v - 0.5f;
    float r = 6.0f * sqrtf(du * du + dv * dv) + 0.6f * fractal(u, v, 4, 3, 40);
    float ring = 0.5f + 0.5f * sinf(2.0f * (float)DX_DS_PI * r);
    mix(out, early, late, ring * ring);
}

// Checks, 4 by 4 per tile, light and mid grey (the colour tints them).
static void checkered_texel(float u, float v, unsigned char *out)
{
    int odd = ((int)(u * 4.0f) + (int)(v * 4.0f)) & 1;
    unsigned char g = odd ? 140 : 240;
    out[0] = out[1] = out[2] = g;
}

// Fills a texture from its texel function and hands it to GL with mipmaps.
static GLuint make_texture(void (*texel)(float, float, unsigned char *))
{
    unsigned char *img = malloc((size_t)TEXTURE_SIZE * TEXTURE_SIZE * 3);
    if (!img) dsError("drawstuff: out of memory for textures");
    for (int y = 0; y < TEXTURE_SIZE; y++)
        for (int x = 0; x < TEXTURE_SIZE; x++)
            texel(((float)x + 0.5f) / TEXTURE_SIZE, ((float)y + 0.5f) / TEXTURE_SIZE,
                  img + 3 * (y * TEXTURE_SIZE + x));
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEXTURE_SIZE, TEXTURE_SIZE, 0, GL_RGB,
                 GL_UNSIGNED_BYTE, img);
    free(img);
    return name;
}

void dxDsTexturesCreate(void)
{
    names[DS_WOOD] = make_texture(wood_texel);
    names[DS_CHECKERED] = make_texture(checkered_texel);
    names[DS_GROUND] = make_texture(ground_texel);
    names[DS_SKY] = make_texture(sky_texel);
}

void dxDsTexturesDestroy(void)
{
    glDeleteTextures(DS_SKY, names + 1);
    for (int i = 0; i <= DS_SKY; i++) names[i] = 0;
}

// Binds a DS_ texture, its texels multiplying the current colour.
void dxDsTextureBind(int texture)
{
    glBindTexture(GL_TEXTURE_2D, names[texture]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}
