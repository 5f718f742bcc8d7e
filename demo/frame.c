/* Lays a show's stages out in equal columns, paints each (backdrop, bodies, caption) and adds
 * the status line: world time, collisions and mode. Text is scaled with the frame height so that
 * it stays readable in a large frame and small in a thumbnail. */
#include "frame.h"

#include <circlecollide.h>
#include <inttypes.h>
#include <stdio.h>

static const char *mode_name(int mode)
{
    return mode == CC_MODE_EXACT ? "EXACT" : mode == CC_MODE_SWEPT ? "SWEPT" : "DISCRETE";
}

void demo_frame_render(demo_canvas *c, demo_show *show)
{
    int k, scale = c->h / 240 > 0 ? c->h / 240 : 1;
    double col_w = (double)c->w / show->nstages;
    double now = show->nstages > 0 ? cc_world_time(show->stage[0].world) : 0.0;
    uint64_t collisions = 0;
    char text[128];

    demo_canvas_fill(c, demo_rgb_make(14.0f, 16.0f, 24.0f));
    for (k = 0; k < show->nstages; ++k) {
        demo_stage *s = &show->stage[k];
        demo_view v = demo_view_fit(&s->def, k * col_w, 0.0, col_w, c->h);
        cc_world_stats st;
        /* each stage stays in its column: a bullet's trail may leave its box, not its panel */
        demo_canvas_clip(c, (int)(k * col_w + 0.5), 0, (int)((k + 1) * col_w + 0.5), c->h);
        if (show->backdrop != NULL)
            show->backdrop(show, k, c, &v);
        demo_render_stage(c, s, &v, cc_world_time(s->world));
        text[0] = '\0';
        if (show->caption != NULL)
            show->caption(show, k, text, sizeof text);
        if (text[0] != '\0')
            demo_render_caption(c, &v, text, scale);
        demo_canvas_unclip(c);
        if (k > 0) /* a thin rule between columns */
            demo_canvas_rect(c, k * col_w - 0.5, 0.0, k * col_w + 0.5, c->h,
                             demo_rgb_make(90.0f, 96.0f, 110.0f), 1.0, DEMO_OVER);
        st.struct_size = sizeof st;
        if (cc_world_get_stats(s->world, &st) == CC_OK)
            collisions += st.collisions;
    }
    if (show->nstages == 1)
        snprintf(text, sizeof text, "T %.2f S   %" PRIu64 " COLLISIONS   %s", now, collisions,
                 mode_name(show->stage[0].def.mode));
    else
        snprintf(text, sizeof text, "T %.2f S", now);
    demo_canvas_rect(c, 0.0, c->h - 11.0 * scale, demo_text_width(text, scale) + 6.0 * scale, c->h,
                     demo_rgb_make(0.0f, 0.0f, 0.0f), 0.55, DEMO_OVER);
    demo_canvas_text(c, 3 * scale, c->h - 9 * scale, scale, text,
                     demo_rgb_make(235.0f, 238.0f, 245.0f));
}
