/* The frame loop. Frame 0 is the initial state; before frame f the scene's control hook runs
 * and every world is stepped to f / fps (computed from f, not accumulated, so that frame times
 * do not drift). Progress goes to stderr, the summary at the end. */
#include "run.h"

#include "frame.h"
#include "platform.h"
#include "ppm.h"
#include "scene.h"

#include <circlecollide.h>
#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

static const char *mode_name(int mode)
{
    return mode == CC_MODE_EXACT ? "EXACT" : mode == CC_MODE_SWEPT ? "SWEPT" : "DISCRETE";
}

static int stage_failed(const demo_show *show)
{
    int k;
    for (k = 0; k < show->nstages; ++k)
        if (show->stage[k].error != 0) {
            fprintf(stderr, "\ncc_demo: %s failed: %s\n", show->stage[k].error_what,
                    cc_result_string(show->stage[k].error));
            return 1;
        }
    return 0;
}

static void summary(demo_show *show, const demo_options *o, double seconds)
{
    int k;
    fprintf(stderr, "cc_demo: %s, %ld frames of %dx%d in %s (frame_0000.ppm to frame_%04ld.ppm)\n",
            o->scene, o->frames, o->width, o->height, o->out, o->frames - 1);
    for (k = 0; k < show->nstages; ++k) {
        const demo_stage *s = &show->stage[k];
        cc_world_stats st;
        memset(&st, 0, sizeof st);
        st.struct_size = sizeof st;
        cc_world_get_stats(s->world, &st);
        fprintf(stderr,
                "  %-8s: world time %.3f, %" PRIu64 " collisions (impulses), %" PRIu64
                " events (impacts, cell crossings, stops: EXACT's work), deepest overlap %.3g\n",
                mode_name(s->def.mode), cc_world_time(s->world), st.collisions, st.events,
                st.max_overlap);
        /* energy the collisions made or lost, the demo's own pushes and brakes left out */
        if (s->def.restitution == 1.0)
            fprintf(stderr, "            energy drift %+.3e (relative; elastic: rounding only)\n",
                    demo_stage_drift(s));
        else if (s->def.rolling_decel > 0.0) /* the world's friction slows them too */
            fprintf(stderr,
                    "            energy lost in collisions and rolling: %.1f%% of the peak kinetic "
                    "energy (restitution %g, rolling deceleration %g)\n",
                    -100.0 * demo_stage_drift(s), s->def.restitution, s->def.rolling_decel);
        else
            fprintf(stderr,
                    "            energy lost in collisions: %.1f%% of the peak kinetic energy "
                    "(restitution %g)\n",
                    -100.0 * demo_stage_drift(s), s->def.restitution);
    }
    if (show->report != NULL)
        show->report(show, stderr);
    fprintf(stderr, "  wall time %.2f s (%.1f frames/s)\n", seconds,
            seconds > 0.0 ? o->frames / seconds : 0.0);
}

int demo_run(const demo_options *o)
{
    demo_show show;
    demo_canvas canvas;
    unsigned char *bytes;
    const demo_scene *scene = demo_find_scene(o->scene);
    size_t npx = (size_t)o->width * (size_t)o->height;
    size_t pathlen = strlen(o->out) + 32;
    char *path;
    /* a terminal gets a live counter, a log file ten lines */
    long f, every = o->frames / (demo_is_terminal_stderr() ? 100 : 10);
    int k, rc = 0;
    double t0 = demo_wall_seconds();
    if (every < 1)
        every = 1;

    if (scene == NULL) {
        fprintf(stderr, "cc_demo: unknown scene '%s'\n", o->scene);
        return 1;
    }
    if (demo_make_dir(o->out) != 0) {
        fprintf(stderr, "cc_demo: cannot create the folder '%s': %s\n", o->out, strerror(errno));
        return 1;
    }
    memset(&show, 0, sizeof show);
    show.opt = o;
    show.dt = 1.0 / o->fps;
    canvas.w = o->width;
    canvas.h = o->height;
    canvas.px = (float *)malloc(npx * 3u * sizeof(float));
    canvas.mask = (float *)calloc(npx, sizeof(float));
    bytes = (unsigned char *)malloc(npx * 3u);
    path = (char *)malloc(pathlen);
    if (canvas.px == NULL || canvas.mask == NULL || bytes == NULL || path == NULL) {
        fprintf(stderr, "cc_demo: out of memory for a %dx%d frame\n", o->width, o->height);
        rc = 1;
        goto done;
    }
    k = scene->build(&show);
    if (k != 0 || stage_failed(&show)) {
        if (k != 0 && !stage_failed(&show))
            fprintf(stderr, "cc_demo: cannot build the scene '%s': %s\n", o->scene,
                    k == -100 ? "out of memory" : cc_result_string(k));
        rc = 1;
        goto done;
    }

    for (f = 0; f < o->frames; ++f) {
        double t = (double)f / o->fps;
        if (f > 0) {
            if (show.control != NULL)
                show.control(&show, f);
            for (k = 0; k < show.nstages; ++k)
                demo_stage_step_to(&show.stage[k], t);
        }
        for (k = 0; k < show.nstages; ++k)
            demo_stage_snapshot(&show.stage[k]);
        if (stage_failed(&show)) {
            rc = 1;
            goto done;
        }
        demo_frame_render(&canvas, &show);
        demo_canvas_to_bytes(&canvas, bytes);
        if (demo_frame_path(path, pathlen, o->out, f) != 0 ||
            demo_ppm_write(path, bytes, o->width, o->height) != 0) {
            fprintf(stderr, "\ncc_demo: cannot write '%s': %s\n", path, strerror(errno));
            rc = 1;
            goto done;
        }
        if ((f + 1) % every == 0 || f + 1 == o->frames)
            fprintf(stderr, "%scc_demo: %s frame %ld/%ld (t = %.3f)%s",
                    demo_is_terminal_stderr() ? "\r" : "", o->scene, f + 1, o->frames, t,
                    demo_is_terminal_stderr() ? "" : "\n");
    }
    if (demo_is_terminal_stderr())
        fprintf(stderr, "\n");
    summary(&show, o, demo_wall_seconds() - t0);

done:
    demo_show_free(&show);
    free(canvas.px);
    free(canvas.mask);
    free(bytes);
    free(path);
    return rc;
}
