/* SPDX-License-Identifier: MIT */
/* raster_int.h — what the rasterizer's files share (not a public API:
 * render.h is the interface, raster.h the contract). */
#ifndef RASTER_INT_H
#define RASTER_INT_H

#include <stddef.h>
#include "raster.h"
#include "raster_num.h"
#include "work.h"

/* Code of the fast path's inner loops: placed in SRAM where the board's
 * build asks for it (RAS_RAM_TEXT: the RP2040 runs from flash through a
 * 16 KB cache otherwise). RP2040_RAM_TEXT=raster (RP2040_RAM_TEXT_RASTER):
 * all of them, in .ram_text; RP2040_RAM_TEXT=1: each in its own section,
 * which the profile of the images places (firmware/board/rp2040/ram_text/on). */
#if defined(RAS_RAM_TEXT) && defined(RP2040_RAM_TEXT_RASTER) && (defined(__GNUC__) || defined(__clang__))
#define RAS_HOT __attribute__((section(".ram_text"), noinline))
#elif defined(RAS_RAM_TEXT) && (defined(__GNUC__) || defined(__clang__))
#define RAS_HOT __attribute__((noinline))
#else
#define RAS_HOT
#endif

#define RAS_MAX_ATTR 8   /* interpolated attributes besides 1/z */
#define RAS_CLIP_MAX 10  /* polygon corners after five planes: 3 + 5, plus slack */

/* A light in camera space: direction toward the light (directional) or
 * position (point); len: a directional light's |v| (v3_len), and div, len
 * as a divisor, made with v once a frame. */
struct ras_light { uint8_t type; num intensity; vec3 v; num len; struct num_divisor div; };

/* Model-space lighting of an instance this frame (light_space = model):
 * on 1 where it applies (raster_shading.c); amb the ambient lights'
 * intensities summed; w[k] a directional light's unit direction toward it
 * in the model's space (the camera-space one turned back by the transpose
 * of the instance's rotation nmat) times its intensity. */
#define RAS_ML_LIGHTS 4
struct ras_mlight { uint8_t on, n; num amb; vec3 w[RAS_ML_LIGHTS]; };

/* Per-frame state of an instance. */
struct ras_inst {
    mat4 m;          /* model -> camera space */
    mat4 nmat;       /* model normal -> camera space (rotations only) */
    uint32_t vbase;  /* first of its vertices in ras_ctx.verts */
    uint32_t tbase;  /* first of its triangles in ras_ctx.tri_rows */
    uint8_t visible; /* survived bounding-sphere culling */
    uint8_t vlit;    /* Gouraud lit per vertex (ras_def.vert_shade), not per corner */
    uint8_t vfit;    /* its vertices to camera space without saturation (ras_mul_point_fit) */
    uint8_t vin;     /* every vertex inside every clipping plane (no ras_point_inside) */
    uint8_t vsplit;  /* vfit's products in 32 bits (ras_mul_point_fit_split's s), 0: none */
    uint8_t nsplit;  /* the same for nmat over normals of RAS_NORMAL_BOX (ras_corner_normal), 0: none */
    struct ras_box box;  /* its model's coordinates (render_init) */
};

/* A transformed vertex: camera space. */
struct ras_vert { vec3 c; };
/* A camera-space vertex transformed again where the frame keeps no table
 * of them (ras_ctx.verts NULL): direct-mapped by vertex, k the vertex's
 * index in the frame (UINT32_MAX: empty), one cache per part of a split
 * preparation. */
struct ras_vcache { uint32_t k; vec3 c; };
/* The book's projection of a vertex (the book path and wireframes only). */
struct ras_proj { num px, py; };

/* A vertex of the default path, projected once per frame (struct ras_pv,
 * raster_num.h): sub-pixel screen position, 1/z and near/z, valid unless
 * sx is RAS_PV_OUT (outside a clipping plane; triangles of three valid
 * corners skip the clipper). A vertex inside every plane lies within two
 * pixels of the viewport, so its position fits 16 bits wherever (render
 * size + 3) << sub_bits stays below 2^15 (240 pixels at 4 bits: 3,888); one
 * that does not fit is marked RAS_PV_OUT too and its triangles take the
 * clipper, which returns such a triangle unchanged and projects it the
 * same way. */
static inline int ras_pv_in(const struct ras_pv *q) { return q->sx != RAS_PV_OUT; }

/* Per-frame facts of a triangle of the default path (ras_def.tri_flags). */
enum { RAS_TRI_FRONT = 1, RAS_TRI_LIVE = 2 };

/* Screen rows a primitive may touch (inclusive); r0 > r1: none. This is the
 * binning of primitives to strips, computed once per frame. */
struct ras_range { int16_t r0, r1; };
struct ras_trows { uint8_t r0, r1; };

/* A texture as RGB565 for the fast path (power-of-two sides, nearest):
 * p == NULL when the texture does not qualify. */
/* The fast path's copy of a texture: RGB565 texels (nearest), or 0x00RRGGBB
 * words (bilinear, which blends the 8-bit channels) */
struct ras_tex565 { const void *p; uint8_t wlog2, hlog2; };

/* Mip chain of a texture, built in work memory when the scene has none. */
#define RAS_MIP_MAX 12   /* levels used: 2048 texels a side down to 1 */
struct ras_mips { uint8_t levels; uint16_t w[RAS_MIP_MAX], h[RAS_MIP_MAX]; const uint8_t *p[RAS_MIP_MAX]; };

#define RAS_FP_LIGHTS 8           /* lights of fast Phong at most */

/* Fast Phong's lights of the current frame in integers (raster_fphong.c). */
struct ras_fphong {
    uint8_t ok;              /* every position fits Q(pq) below 2^14 this frame */
    int8_t pq;               /* camera-space positions in Q(pq) */
    uint8_t nl, diffuse, specular;
    int32_t ambient;         /* Q14 */
    struct { uint8_t type; int32_t li; int32_t v[3]; } l[RAS_FP_LIGHTS];
                             /* li Q14; v: unit direction toward the light in Q14
                                (directional) or position in Q(pq) (point) */
};
/* The state of the strip being drawn (raster_strip sets it). */
struct ras_cur {
    struct render_target *t;
    struct render_stats *st;
    /* depth test of ras_fill_triangle: RAS_DEPTH_LESS_WRITE (normal),
     * RAS_DEPTH_EQUAL (shading pass after a depth pass), RAS_DEPTH_BEHIND
     * (shadow-volume fragments behind the surface: depth-fail) */
    uint8_t depth_func;
    uint8_t depth_only;      /* render_triangle writes depth, no colour */
    uint8_t lean;            /* ras_default_lean: the pass's triangles may take the lean path */
};

/* The default path's own state (book_exact = 0, not wireframe). */
struct ras_def {
    uint8_t sub_bits;        /* sub-pixel bits */
    uint8_t shading;         /* the shading it draws (Phong lit at the corners is Gouraud) */
    int8_t affine_from;      /* attributes from this index on are interpolated linearly in
                                screen space (uv = linear), -1: all perspective-correct */
    num near_z;              /* near clipping plane (camera space z) */
    num side_x, side_y;      /* side planes: |x| <= side_x*z, |y| <= side_y*z */
    num side_xk, side_yk;    /* sqrt(1 + side^2): a side plane's value over the distance */
    struct ras_front front;  /* front faces known from the screen (raster_num.h) */
    struct ras_mips *mips;   /* per texture */
    uint8_t *mip_mem;        /* the chains the scene has not: raster_work.c's, texture by texture */
    /* per frame: projected vertices, triangle flags and the lighting of
     * Gouraud corners or flat faces (NULL when not kept) */
    struct ras_pv *pv;
    uint8_t *tri_flags;      /* RAS_TRI_*; NULL with back faces culled: the strips visit
                                only live triangles (a dead one's rows are none), and a
                                live one then faces the camera */
    num *tri_shade;          /* 3 a triangle: Gouraud corners, or the flat intensity first */
    num *vert_shade;         /* Gouraud lighting of each vertex of vertex-lit instances
                                (ras_inst.vlit), made when a live triangle first uses it,
                                by either part of a split preparation: a vertex's lighting
                                depends on the vertex only, so both parts store the same
                                bits, and nothing reads it before both have returned */
    struct ras_mlight *mlight;   /* per instance (light_space = model), NULL: none */
    uint8_t *vert_lit;       /* one bit a vertex: vert_shade made this frame by part 0, */
    uint8_t *vert_lit1;      /* and by part 1 (raster_frame_triangles), in the sibling's
                                work memory (each part writes only its own bits); NULL: no
                                sibling */
    struct ras_vcache *vcache;   /* camera-space vertices of the frame's culling and lighting
                                    (ras_cam_vertex) where ras_ctx.verts is not kept, */
    struct ras_vcache *vcache1;  /* and part 1's (the sibling's work memory); NULL: none */
    uint16_t vcache_mask;        /* entries - 1 */
};

/* The fast span path's own state (the default path with perspective_step > 1). */
struct ras_fast {
    uint8_t on;              /* triangles try the fast span loops */
    uint8_t persp_log2;      /* a reciprocal every 2^persp_log2 pixels */
    uint8_t phong;           /* Phong by fast Phong (lighting = fast) */
    uint16_t nkeep;          /* kept set-ups, a power of two (triangle i in slot i % nkeep) */
    uint8_t keep_on;         /* the slots used this frame: its strips draw at most
                                2 nkeep triangles each on average (raster_frame_finish);
                                more, and the next strip's triangles take the slots first */
    struct ras_tex565 *tex565;   /* per texture */
    uint8_t *tex_mem;            /* the RGB565 copies, texture by texture */
    struct ras_fast_state *keep; /* triangle set-ups kept between strips */
    const uint16_t *spec_tab;    /* fast Phong's specular tables, 257 entries each */
    const uint32_t *spec_step;   /* per table: index step and end (ras_spec_table) */
    int16_t *inst_spec;      /* per instance: its table, -1: no highlight, -2: none left */
    struct ras_fphong fp;    /* fast Phong's lights, per frame */
    struct ras_colour_memo {  /* the last colour fast_describe converted (a mesh's
                                 triangles mostly share one): its RGB565 and bytes,
                                 its Gouraud levels */
        rgb c, ck;
        uint16_t c565;
        uint8_t c888[3];
        uint8_t valid, kvalid, kok;
        uint32_t kr, kg, kb;
    } memo;
};

/* Chapter 15's own state (raster_ch15.c; default path, Phong shading). */
struct ras_c15 {
    int8_t sh_light;         /* light casting shadows, -1: none */
    uint8_t sm_on, sv_on, env_on, pcf;
    uint8_t sm_ortho;        /* directional light: orthographic map */
    uint16_t sm_size;
    uint16_t *smap;          /* sm_size^2 closeness values (larger is nearer the light) */
    vec3 sm_o, sm_r, sm_u, sm_f;  /* light frame in camera space: origin, right, up, forward */
    num sm_scale;            /* texels per unit (ortho) or per unit of x/z (perspective) */
    num sm_near, sm_texel;   /* perspective near distance; texel size at distance 1 (or world) */
    vec3 bound_c;            /* bounding sphere of every instance, camera space */
    num bound_r;
    num env_k;               /* environment fraction */
    uint16_t *adj;           /* per triangle 3 neighbours across its edges (RAS_NO_ADJ: none) */
    uint8_t *stencil;        /* strip_rows * w stencil counts (shadow volumes) */
};

/* The default path's triangles binned to strips (raster_frame.c sorts
 * them, raster_strip.c walks them): each frame, the live triangles
 * (neither culled nor degenerate, with a pixel centre on screen) in order
 * of the bucket of strip_rows rows their first row falls in, stable, so
 * each bucket's run is in the scene's drawing order, and per bucket the
 * last row its triangles reach. A strip merges the runs of the buckets
 * begun up to its last row that reach it, by triangle index: the scene's
 * drawing order, with no state from one strip to the next (strips in any
 * order). off: every triangle of every instance is tested against every
 * strip (the book path, wireframes, more than 65535 triangles). */
struct ras_bins {
    uint8_t on;
    uint16_t nbuckets;
    uint16_t *order;         /* live triangles by bucket of their first row (ntris) */
    uint16_t *start;         /* nbuckets + 1: bucket b is order[start[b] .. start[b + 1]) */
    int16_t *reach;          /* nbuckets: the last row of bucket b's triangles, -1: none */
    uint16_t *runs;          /* 2 nbuckets: a strip's runs being merged (cursor, end) */
    uint32_t div_mul;        /* row r's bucket is (r * div_mul) >> 16 for every row
                                (render_init checks them all); 0: r / strip_rows */
};

/* A sibling context's own tables (raster_init_sibling): what its strips
 * write; everything else is its owner's, copied at each frame. */
struct ras_own {
    uint8_t *depth;
    uint16_t *runs;
    struct ras_fast_state *keep;
    uint8_t *stencil;
    struct ras_vcache *vcache;   /* the owner's part-1 camera-space vertices (ras_def.vcache1) */
    uint8_t *vlit;           /* the owner's part-1 vertices lit (ras_def.vert_lit1) */
};

/* The rasterizer's state, in the caller's work memory: what every path
 * uses, then the state each path owns. */
struct ras_ctx {
    const struct scene *s;
    uint16_t w, h, strip_rows;
    uint8_t book;            /* ras_options.book_exact */
    uint8_t depth_bytes;     /* 2, 4 or sizeof(num) (book path); 0: no depth test */
    struct ras_cur cur;
    num cw, vw, vh, d;       /* render width, viewport (aspect-corrected), projection plane */
    num unproj;              /* cw*d/vw: canvas units per unit of x/z */
    num scale2d;             /* render height / scene canvas height */
    mat4 cam, cam_rot_t;     /* camera matrix; transposed camera rotation */
    vec3 cam_pos;            /* world-space camera position (the book's view-vector quirk) */
    uint32_t nverts, ntris;
    uint32_t tris_in, tris_drawn;
    uint32_t part_in[2], part_drawn[2];  /* the same counted by the parts of the triangles */
    struct ras_inst *inst;
    struct ras_vert *verts;  /* per vertex; NULL where the default path transforms them
                                again when needed (ras_cam_vertex) */
    struct ras_proj *proj;   /* per vertex; NULL on the default path, which projects in ras_pv */
    struct ras_trows *tri_rows;  /* per triangle (ras_trows_pack) */
    uint8_t row_shift;           /* of tri_rows: 0 up to 256 rows, else the least that fits */
    struct ras_range *prim_rows, *line_rows;
    struct ras_light *lights;
    uint8_t *depth;          /* strip_rows * w entries */
    struct ras_def def;
    struct ras_bins bins;
    struct ras_fast fast;
    struct ras_c15 c15;
    const struct ras_ctx *owner;   /* a sibling's owner (raster_init_sibling), NULL: none */
    struct ras_own own;            /* a sibling's own tables */
};

/* Camera-space position of vertex k of an instance this frame where
 * ras_ctx.verts is not kept: transformed again from the model (through
 * cache vc, NULL: none), the same bits (ras_cam_vertex). */
vec3 ras_cam_vertex_again(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                          const struct ras_model *m, uint32_t k, struct ras_vcache *vc);

/* Camera-space position of vertex k of an instance this frame: from
 * ras_ctx.verts where kept, else ras_cam_vertex_again's. */
static inline vec3 ras_cam_vertex(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                                  const struct ras_model *m, uint32_t k, struct ras_vcache *vc)
{
    if (rc->verts) return rc->verts[ri->vbase + k].c;
    return ras_cam_vertex_again(rc, in, ri, m, k, vc);
}

/* A triangle's rows in the frame's table (ras_ctx.tri_rows), a byte each:
 * its first and last row >> row_shift, so the rows it stands for
 * (ras_trows_first .. ras_trows_last) include the triangle's, the same rows
 * up to 256 rows a frame; r0 > r1: none. */
static inline struct ras_trows ras_trows_pack(const struct ras_ctx *rc, struct ras_range r)
{
    struct ras_trows p = { 1, 0 };
    if (r.r0 <= r.r1) {
        p.r0 = (uint8_t)((uint32_t)r.r0 >> rc->row_shift);
        p.r1 = (uint8_t)((uint32_t)r.r1 >> rc->row_shift);
    }
    return p;
}
static inline int32_t ras_trows_first(const struct ras_ctx *rc, struct ras_trows p)
{
    return (int32_t)((uint32_t)p.r0 << rc->row_shift);
}
static inline int32_t ras_trows_last(const struct ras_ctx *rc, struct ras_trows p)
{
    return (int32_t)((((uint32_t)p.r1 + 1) << rc->row_shift) - 1);
}

/* Triangle gi's facts this frame set to f (where kept); f != 0: live. */
static inline int ras_tri_flag(struct ras_ctx *rc, uint32_t gi, int f)
{
    if (rc->def.tri_flags) rc->def.tri_flags[gi] = (uint8_t)f;
    return f != 0;
}

/* Triangle gi's facts this frame, of a triangle the strips visit (live). */
static inline uint8_t ras_tri_flags(const struct ras_ctx *rc, uint32_t gi)
{
    return rc->def.tri_flags ? rc->def.tri_flags[gi] : (uint8_t)(RAS_TRI_LIVE | RAS_TRI_FRONT);
}

/* The state in the caller's work memory, at its first WORK_ALIGN boundary
 * (raster_work_size counts the slack). */
static inline struct ras_ctx *ras_ctx_of(void *work)
{
    uintptr_t p = (uintptr_t)work;
    return (struct ras_ctx *)((p + (WORK_ALIGN - 1)) & ~(uintptr_t)(WORK_ALIGN - 1));
}

enum { RAS_DEPTH_LESS_WRITE = 0, RAS_DEPTH_EQUAL = 1, RAS_DEPTH_BEHIND = 2 };
#define RAS_NO_ADJ 0xFFFFu

/* ---- pixel writes (raster_lines.c) ---- */
/* Screen pixel; ignored outside the current strip. */
void ras_put(struct ras_ctx *rc, int col, int row, rgb c);
/* The book's PutPixel: column w/2 + T(x), row h/2 - T(y) - 1. */
void ras_put_canvas(struct ras_ctx *rc, num x, num y, rgb c);
int ras_canvas_col(const struct ras_ctx *rc, int32_t x);
int ras_canvas_row(const struct ras_ctx *rc, int32_t y);

/* ---- chapter 6: lines ---- */
/* The book's DrawLine of raster-01 (one slope for every line) and DrawLine;
 * DrawWireframeTriangle. */
void ras_draw_line_broken(struct ras_ctx *rc, num x0, num y0, num x1, num y1, rgb c);
void ras_draw_line(struct ras_ctx *rc, num x0, num y0, num x1, num y1, rgb c);
void ras_draw_wireframe_triangle(struct ras_ctx *rc, const num x[3], const num y[3], rgb c);

/* ---- chapters 7, 8: the book's scan conversion (raster_triangles.c) ---- */
/* Called per pixel with integer canvas coordinates and the span's attributes. */
typedef void (*ras_book_pixel_fn)(struct ras_ctx *rc, int32_t x, int32_t y, const num *q, void *ud);
/* Sort order of the book (docs/book-demos.md, "Filled and shaded
 * triangles", step 1): idx[] receives corner indices. */
void ras_book_sort_corners(const num y[3], int idx[3]);
/* Steps 2–5 of the same on corners already sorted by y; nq attributes q[k][corner];
 * truncated spans (raster-04 and every 3D demo). */
/* (The book's DrawFilledTriangle / DrawShadedTriangle scan.) */
void ras_book_scan_triangle(struct ras_ctx *rc, const num x[3], const num y[3], int nq,
                            const num (*q)[3], ras_book_pixel_fn fn, void *ud);
/* The book's DrawFilledTriangle and DrawShadedTriangle. */
void ras_draw_filled_triangle(struct ras_ctx *rc, const num x[3], const num y[3], rgb c);
void ras_draw_shaded_triangle(struct ras_ctx *rc, const num x[3], const num y[3], const num h[3], rgb c);

/* ---- RenderTriangle of each path (raster_book.c, raster_default.c) ---- */
/* The book path's triangle (and every wireframe), into the current strip. */
void ras_book_render_triangle(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                              const struct ras_model *m, const struct ras_triangle *t);
/* The default path's triangle gi (its index in the frame's tables). */
void ras_default_render_triangle(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                                 const struct ras_model *m, const struct ras_triangle *t, uint32_t gi);
/* 1 when the current pass's default-path triangles may take its lean path
 * (ras_cur.lean; set by render_scene for each pass). */
int ras_default_lean(const struct ras_ctx *rc);
/* 1 when instance in's Gouraud corners are lit per vertex (raster_work.c). */
int ras_vertex_lit(const struct scene *s, const struct ras_instance *in);
/* Per frame: the facts of the default path's triangle gi kept for every
 * strip, and the lighting of its Gouraud corners or flat face; 1 when it
 * is live. known: a front face known from its projected corners
 * (ras_front_known, made by the caller). */
int ras_tri_cache(struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                  const struct ras_model *m, const struct ras_triangle *t, uint32_t gi, int part, int known);

/* ---- the default path's exact fill (raster_triangles.c) ---- */
struct ras_sv {
    int32_t x, y;            /* screen position in 1/2^sub_bits pixel, y down */
    num iz;                  /* 1/z */
    uint32_t depth;          /* near/z, 32-bit fraction */
    num a[RAS_MAX_ATTR];     /* attributes, interpolated perspective-correctly */
};
/* Called for each pixel that passes the depth test; a[] interpolated, z the
 * camera-space depth of the pixel. */
typedef void (*ras_pixel_fn)(struct ras_ctx *rc, int col, int row, const num *a, num z, void *ud);
/* Fills a triangle whose corners run clockwise on screen (non-positive area
 * draws nothing). Returns the number of pixels that passed the depth test
 * (rc->cur.depth_func). fn == NULL: depth only; na < 0: fn gets no attributes
 * and z = 0 (stencil updates). */
uint32_t ras_fill_triangle(struct ras_ctx *rc, const struct ras_sv *v0, const struct ras_sv *v1,
                           const struct ras_sv *v2, int na, ras_pixel_fn fn, void *ud);
/* Edge function of edge a->b at p, in sub-pixel units squared: positive on
 * the interior side of a clockwise (on screen) triangle. */
int64_t ras_edge(int32_t ax, int32_t ay, int32_t bx, int32_t by, int64_t px, int64_t py);
/* Box of the corners in sub-pixel units: min x, min y, max x, max y. */
void ras_sub_box(const struct ras_sv *v0, const struct ras_sv *v1, const struct ras_sv *v2, int32_t box[4]);

/* What the default path's exact pixels of a triangle need (ud of
 * ras_default_pixel). */
struct ras_def_tri {
    rgb color;
    num flat_i, spec;
    int shading, tex;
    int ai_i, ai_n, ai_uv, ai_p; /* attribute slots */
    num lod_base, iz_eff;    /* trilinear: texels^2 per pixel at depth 1/iz_eff */
    int nmap;                /* normal map texture, -1: none */
    vec3 tan_u, tan_v;       /* unit tangents along +u and toward the image's top (-v) */
};
/* The default path's pixel (raster_pixel.c), a ras_pixel_fn. */
void ras_default_pixel(struct ras_ctx *rc, int col, int row, const num *a, num z, void *ud);

/* ---- the default path's fast triangle (raster_fast.c; its span loops
 * raster_spans*.c, their parameters raster_fast.h; fast Phong raster_fphong.c) ---- */
#define RAS_FAST_NA 8             /* attributes of the fast path at most */
/* Lights of the frame into rc->fast.fp (after the camera-space lights and vertices). */
void ras_fphong_frame(struct ras_ctx *rc);
/* cos^e at 257 points in Q14 (fast Phong looks it up); step[0]
 * receives the index step, Q16 index units per Q14 unit of 1 - cos, and
 * step[1] the value of 1 - cos (Q14) from which on the table gives 0. */
void ras_spec_table(uint16_t t[257], uint32_t e, uint32_t step[2]);
struct ras_fast_tri {
    uint8_t shade, src;      /* the span loop's SPAN_SHADE_*, SPAN_SRC_* (raster_fast.h) */
    uint16_t c565;           /* flat: the colour */
    uint8_t c888[3];         /* flat: the colour before quantisation (host output) */
    uint32_t kr, kg, kb;     /* Gouraud (saturating): colour in RGB565 levels, Q10 */
    const void *tex;         /* textured: RGB565 texels, or 0x00RRGGBB words (bilinear) */
    uint32_t wmask, hmask, wlog2;
    int32_t uscale, vscale;  /* u, v to 16.16 texel coordinates */
    int ai_i, ai_uv;         /* attribute slots of intensity and u, v in ras_sv.a */
    int ai_n, ai_p;          /* fast Phong: slots of the normal and the camera-space position */
    const uint16_t *spec;    /* fast Phong: specular table (ras_spec_table), NULL: none */
    uint32_t spec_scale, spec_umax; /* index step; 1 - cos (Q14) past the table's end */
    const struct ras_fphong *fp;
};
/* A triangle's set-up kept from one strip to the next (raster_fast.c). */
struct ras_fast_state { uint64_t mem[64]; uint32_t tri; };
/* Fills a triangle (clockwise on screen) with the fast span loops, depth
 * test RAS_DEPTH_LESS_WRITE, in the current strip. Returns the pixels
 * written, or -1 (nothing drawn) when the triangle does not fit the fast
 * path's 32-bit stepping: the caller then uses ras_fill_triangle. With
 * keep != NULL the set-up is left there for the next strip. */
int32_t ras_fast_fill(struct ras_ctx *rc, const struct ras_sv *v0, const struct ras_sv *v1, const struct ras_sv *v2,
                      const struct ras_fast_tri *ft, struct ras_fast_state *keep);
/* Continues a kept triangle in the current strip when it stopped at the
 * row above it: 1 (rows drawn, *drawn pixels), 0 (not kept for this strip). */
int ras_fast_resume(struct ras_ctx *rc, struct ras_fast_state *keep, uint32_t *drawn);

/* ---- face normals and projections kept wide (raster_project.c) ---- */
/* Face normal (b - a) x (c - a) of camera-space corners, in wnum. Its
 * components reach the square of the triangle's extent (an instance's
 * diameter squared, far more for an extruded shadow-volume face), which
 * `num` need not hold; each component is v3_cross's, operation for
 * operation, so wnum_to_num of it gives v3_cross's bits. */
struct ras_wnormal { wnum x, y, z; };
struct ras_wnormal ras_face_normal_wide(vec3 a, vec3 b, vec3 c);
/* wnum_to_num of each component: the face normal as v3_cross gives it. */
vec3 ras_wnormal_narrow(struct ras_wnormal n);
vec3 ras_wnormal_narrow_dir(struct ras_wnormal n);
/* (-p) . n summed in wnum, in v3_dot's operand order (x, y, z): positive
 * when the face is seen from its front from the camera at the origin.
 * |p| |n| need not fit `num`. */
wnum ras_facing_wide(vec3 p, struct ras_wnormal n);
/* x * z / unproj with the product kept wide: the unprojection of a pixel
 * at depth z (and the projection x * unproj / z, arguments swapped). The
 * result needs to fit `num`, the product not; the same bits as
 * num_div(num_mul(x, z), unproj) whenever that product fits. */
num ras_mul_div(num x, num z, num unproj);

/* ---- chapters 9, 10: projection and transforms (raster_project.c) ---- */
/* The book's ProjectVertex (with ViewportToCanvas). */
void ras_project_vertex(const struct ras_ctx *rc, vec3 v, num *x, num *y);
/* The default path's projection: screen position of a camera-space point
 * inside the clip volume in sub-pixel units (y down). */
void ras_project_sub(const struct ras_ctx *rc, vec3 p, int32_t *sx, int32_t *sy);
/* ras_project_sub with num_recip(p.z) and ras_depth32(near_z, p.z), the
 * same bits, the four divisions by p.z made as one (ras_div_depth). */
void ras_project_sub_depth(const struct ras_ctx *rc, vec3 p, int32_t *sx, int32_t *sy, num *iz, uint32_t *depth);
/* ras_project_sub_depth's constants now (ras_div_sub: the same bits from
 * one call a point). */
void ras_subproj_of(const struct ras_ctx *rc, struct ras_subproj *k);
/* Scene canvas to render canvas (2D primitives): v*h/canvas_h, one rounding. */
num ras_scale_canvas(const struct ras_ctx *rc, num v);
/* A model-space corner normal in camera space (the instance's rotations). */
vec3 ras_corner_normal(const struct ras_inst *ri, vec3 n);
mat4 ras_instance_matrix(const struct ras_instance *in, uint16_t frame);
mat4 ras_camera_matrix(const struct scene *s, uint16_t frame, mat4 *rot_t, vec3 *pos);
mat3 ras_instance_rotation(const struct ras_instance *in, uint16_t frame);

/* ---- chapter 11: clipping (raster_clip.c) ---- */
/* Bounding-sphere test of an instance against the book's five planes. */
int ras_instance_visible(const struct ras_ctx *rc, const struct ras_inst *ri,
                         const struct ras_model *m, num scale);
/* The book's triangle test: 1 when all corners are strictly inside all planes. */
int ras_triangle_inside(vec3 a, vec3 b, vec3 c);
/* A clipped polygon corner: camera-space position plus attributes. */
struct ras_cv { vec3 p; num a[RAS_MAX_ATTR]; };
/* The book's ClipTriangle: Sutherland–Hodgman against the default path's planes;
 * returns the corner count of out (0, or 3..RAS_CLIP_MAX). */
int ras_clip_triangle(const struct ras_ctx *rc, const struct ras_cv in[3], int na, struct ras_cv *out);
/* 1 when p is inside every plane of ras_clip_triangle (a triangle of three such
 * corners comes out of it unchanged). */
int ras_point_inside(const struct ras_ctx *rc, vec3 p);
/* 1 when every point of camera-space box b (ras_box_transform's) passes
 * ras_point_inside: the test at the box's extreme corners, each of its
 * operations monotonic. */
int ras_box_inside(const struct ras_ctx *rc, const struct ras_box *b);

/* ---- chapter 13: lighting (raster_shading.c) ---- */
/* The book's ComputeIllumination (chapter 13). */
num ras_compute_illumination(const struct ras_ctx *rc, vec3 p, vec3 n, num specular);
/* light_space = model: instance in's model-space lights this frame (after
 * its nmat and the frame's lights), and a vertex's lighting from its model
 * normal n (unit length). */
void ras_model_light_frame(const struct ras_ctx *rc, const struct ras_instance *in, const struct ras_inst *ri,
                           struct ras_mlight *ml);
num ras_model_light(const struct ras_mlight *ml, vec3 n);
/* The same with light `shadow_k` (or none if < 0) scaled by vis in [0, 1]. */
num ras_compute_illumination_vis(const struct ras_ctx *rc, vec3 p, vec3 n, num specular, int shadow_k, num vis);

/* ---- chapter 15 (raster_ch15.c): default path, Phong shading ---- */
/* Work memory beyond the chapters 6-14 layout. */
size_t ras_ch15_adj_size(const struct scene *s, uint32_t ntris);
size_t ras_ch15_smap_size(const struct scene *s);
size_t ras_ch15_stencil_size(const struct scene *s, uint16_t w, uint16_t strip_rows);
/* render_init: flags and triangle adjacency. */
void ras_ch15_init(struct ras_ctx *rc);
/* render_begin_frame, after the transforms: scene bounds, light frame,
 * the shadow map. */
void ras_ch15_frame(struct ras_ctx *rc);
/* Visibility of the shadow light at camera-space p with unit normal n, in
 * [0, 1] (shadow map with PCF); 1 when the map is off. */
num ras_shadow_map_vis(const struct ras_ctx *rc, vec3 p, vec3 n);
/* Shadow volumes of the current strip into rc->c15.stencil (after a depth pass). */
void ras_shadow_volumes(struct ras_ctx *rc);
/* Environment colour seen along camera-space direction r (procedural sky
 * and ground in world space). */
rgb ras_env_colour(const struct ras_ctx *rc, vec3 r);

/* ---- chapter 14: textures (raster_texture.c) ---- */
/* The demos' lookups (nearest / raster-13 bilinear); *nan set when the
 * address falls outside the image (the demos store such channels as 0). */
rgb ras_texel_book(const struct ras_texture *t, num u, num v, int *nan);
/* Default path: filter of the texture, clamped addressing; lod = log2 of
 * texels per pixel (trilinear only). */
rgb ras_sample(const struct ras_ctx *rc, int tex, num u, num v, num lod);
num ras_log2(num x);
size_t ras_mips_size(const struct ras_texture *t);
void ras_mips_build(const struct ras_texture *t, struct ras_mips *m, uint8_t *mem);

#endif
