/* Draws a stage in the order a viewer reads it: trails under the bodies, walls, the bodies in
 * their speed colours, then the contact flashes as additive light on top. Sizes in pixels are
 * derived from world sizes so that one scene looks the same at every frame size. */
#include "render.h"

#include "colour.h"

#include <math.h>

demo_view demo_view_fit(const demo_stage_def *d, double vx, double vy, double vw, double vh)
{
    demo_view v;
    double w = d->x1 - d->x0, h = d->y1 - d->y0;
    double sx = vw / w, sy = vh / h;
    v.scale = sx < sy ? sx : sy;
    v.ox = vx + 0.5 * (vw - w * v.scale);
    v.oy = vy + 0.5 * (vh - h * v.scale);
    v.x0 = d->x0;
    v.y1 = d->y1;
    v.vx = vx;
    v.vy = vy;
    v.vw = vw;
    v.vh = vh;
    return v;
}

double demo_view_x(const demo_view *v, double x)
{
    return v->ox + (x - v->x0) * v->scale;
}

double demo_view_y(const demo_view *v, double y)
{
    return v->oy + (v->y1 - y) * v->scale;
}

static double speed_of(const cc_circle *c)
{
    return sqrt(c->vel.x * c->vel.x + c->vel.y * c->vel.y);
}

static void draw_trail(demo_canvas *c, const demo_stage *s, const demo_view *v, int id,
                       const cc_circle *body, double now)
{
    const demo_trail *tr = &s->trails[id];
    double life = s->def.trail_time;
    double rpx = body->radius * v->scale;
    demo_rgb col = demo_speed_colour(speed_of(body) / s->def.speed_ref);
    int k;
    demo_mask_begin(c);
    for (k = 0; k + 1 < tr->count; ++k) {
        /* oldest first: slot head - count is the oldest */
        int i0 = (tr->head - tr->count + k + 2 * DEMO_TRAIL_POINTS) % DEMO_TRAIL_POINTS;
        int i1 = (i0 + 1) % DEMO_TRAIL_POINTS;
        const demo_point *p = &tr->p[i0], *q = &tr->p[i1];
        double age = now - 0.5 * (p->t + q->t);
        double fade;
        if (age >= life || p->t > now || q->t > now || (p->x == q->x && p->y == q->y))
            continue;
        fade = 1.0 - (age < 0.0 ? 0.0 : age) / life;
        demo_mask_capsule(c, demo_view_x(v, p->x), demo_view_y(v, p->y), demo_view_x(v, q->x),
                          demo_view_y(v, q->y), 0.25 + 0.55 * rpx * fade, 0.5 * fade, col,
                          DEMO_OVER);
    }
    demo_mask_end(c, col, DEMO_OVER);
}

static void draw_body(demo_canvas *c, const demo_stage *s, const demo_view *v, int id,
                      const cc_circle *body)
{
    double x = demo_view_x(v, body->pos.x), y = demo_view_y(v, body->pos.y);
    double r = body->radius * v->scale;
    int style = id < s->def.max_circles ? s->style_of[id] : DEMO_STYLE_SPEED;
    demo_rgb dark = demo_rgb_make(16.0f, 18.0f, 26.0f);
    if (style == DEMO_STYLE_HIDDEN)
        return;
    if (style == DEMO_STYLE_SOLID) {
        demo_canvas_disc(c, x, y, r, demo_rgb_make(172.0f, 178.0f, 190.0f), 1.0, DEMO_OVER);
        demo_canvas_disc(c, x, y, 0.45 * r, demo_rgb_make(110.0f, 116.0f, 130.0f), 1.0, DEMO_OVER);
    } else {
        demo_canvas_disc(c, x, y, r, demo_speed_colour(speed_of(body) / s->def.speed_ref), 1.0,
                         DEMO_OVER);
        if (style == DEMO_STYLE_MARKED) {
            double hw = 0.12 * r < 0.6 ? 0.6 : 0.12 * r;
            demo_canvas_ring(c, x, y, r - hw, hw, demo_rgb_make(250.0f, 250.0f, 250.0f), 1.0,
                             DEMO_OVER);
        }
    }
    if (r >= 4.0) /* a thin dark rim keeps touching bodies apart to the eye */
        demo_canvas_ring(c, x, y, r - 0.5, 0.5, dark, 0.6, DEMO_OVER);
}

/* A periodic box: positions are in [0, period), and a circle within a radius of a wrapped edge
 * is painted there and at its image beyond the opposite edge (both, or all four near a corner),
 * inside the box's pixel rectangle only. */
static void draw_periodic_bodies(demo_canvas *c, const demo_stage *s, const demo_view *v)
{
    const double px = s->period.x, py = s->period.y;
    int was_clipped = c->clipped, cx0 = c->cx0, cy0 = c->cy0, cx1 = c->cx1, cy1 = c->cy1;
    int bx0 = 0, by0 = 0, bx1 = c->w, by1 = c->h, i;
    if (px > 0.0) {
        bx0 = (int)floor(demo_view_x(v, 0.0) + 0.5);
        bx1 = (int)floor(demo_view_x(v, px) + 0.5);
    }
    if (py > 0.0) {
        by0 = (int)floor(demo_view_y(v, py) + 0.5);
        by1 = (int)floor(demo_view_y(v, 0.0) + 0.5);
    }
    if (was_clipped) { /* inside the stage's column too */
        bx0 = bx0 > cx0 ? bx0 : cx0;
        by0 = by0 > cy0 ? by0 : cy0;
        bx1 = bx1 < cx1 ? bx1 : cx1;
        by1 = by1 < cy1 ? by1 : cy1;
    }
    demo_canvas_clip(c, bx0, by0, bx1, by1);
    for (i = 0; i < s->count; ++i) {
        const cc_circle *b = &s->circles[i];
        int ix, iy;
        for (iy = -1; iy <= 1; ++iy)
            for (ix = -1; ix <= 1; ++ix) {
                cc_circle img = *b;
                if ((ix != 0 && !(px > 0.0)) || (iy != 0 && !(py > 0.0)))
                    continue;
                img.pos.x += ix * px;
                img.pos.y += iy * py;
                /* only images that reach into the box */
                if ((px > 0.0 && (img.pos.x + img.radius <= 0.0 || img.pos.x - img.radius >= px)) ||
                    (py > 0.0 && (img.pos.y + img.radius <= 0.0 || img.pos.y - img.radius >= py)))
                    continue;
                draw_body(c, s, v, s->ids[i], &img);
            }
    }
    if (was_clipped)
        demo_canvas_clip(c, cx0, cy0, cx1, cy1);
    else
        demo_canvas_unclip(c);
}

static void draw_flashes(demo_canvas *c, const demo_stage *s, const demo_view *v, double now)
{
    int k;
    double life = s->def.flash_time;
    demo_rgb warm = demo_rgb_make(255.0f, 236.0f, 190.0f);
    for (k = 0; k < s->flash_count; ++k) {
        const demo_flash *f = &s->flashes[k];
        double age = now - f->t, u, a, r;
        if (age < 0.0 || age >= life)
            continue;
        u = age / life;
        a = (0.35 + 0.65 * f->strength) * (1.0 - u) * (1.0 - u);
        r = s->def.flash_radius * v->scale * (0.5 + 0.5 * u);
        if (r < 1.5)
            r = 1.5;
        /* a soft glow: three nested discs of light, brightest at the contact point */
        demo_canvas_disc(c, demo_view_x(v, f->x), demo_view_y(v, f->y), r, warm, 0.2 * a, DEMO_ADD);
        demo_canvas_disc(c, demo_view_x(v, f->x), demo_view_y(v, f->y), 0.6 * r, warm, 0.3 * a,
                         DEMO_ADD);
        demo_canvas_disc(c, demo_view_x(v, f->x), demo_view_y(v, f->y), 0.3 * r, warm, 0.5 * a,
                         DEMO_ADD);
    }
}

void demo_render_stage(demo_canvas *c, const demo_stage *s, const demo_view *v, double now)
{
    int i;
    double hw = 0.002 * (c->h < c->w ? c->h : c->w);
    demo_rgb wall = demo_rgb_make(205.0f, 210.0f, 222.0f);
    if (hw < 0.75)
        hw = 0.75;
    if (s->def.trail_time > 0.0)
        for (i = 0; i < s->count; ++i)
            if (s->ids[i] < s->def.max_circles && s->style_of[s->ids[i]] != DEMO_STYLE_HIDDEN)
                draw_trail(c, s, v, s->ids[i], &s->circles[i], now);
    for (i = 0; i < s->nwalls; ++i)
        demo_canvas_capsule(c, demo_view_x(v, s->walls[i].a.x), demo_view_y(v, s->walls[i].a.y),
                            demo_view_x(v, s->walls[i].b.x), demo_view_y(v, s->walls[i].b.y), hw,
                            wall, 1.0, DEMO_OVER);
    if (s->period.x > 0.0 || s->period.y > 0.0)
        draw_periodic_bodies(c, s, v);
    else
        for (i = 0; i < s->count; ++i)
            draw_body(c, s, v, s->ids[i], &s->circles[i]);
    if (s->def.flash_time > 0.0)
        draw_flashes(c, s, v, now);
}

void demo_render_caption(demo_canvas *c, const demo_view *v, const char *text, int scale)
{
    int w = demo_text_width(text, scale);
    int x = (int)(v->vx + 0.5 * (v->vw - w));
    int y = (int)v->vy + 2 * scale;
    if (w + 4 * scale > v->vw)
        return; /* a caption cut off at both ends says nothing: leave it out */
    demo_canvas_rect(c, x - 2 * scale, y - scale, x + w + 2 * scale, y + 8 * scale,
                     demo_rgb_make(0.0f, 0.0f, 0.0f), 0.55, DEMO_OVER);
    demo_canvas_text(c, x, y, scale, text, demo_rgb_make(235.0f, 238.0f, 245.0f));
}
