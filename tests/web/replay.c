/* web_replay: repeats a session of the web page (demo/web/) with the native library and prints
 * the world's state in the page's own format (circlecollide.js stateText()):
 *   time <bits>            world time
 *   hash <16 hex digits>   cc_world_hash
 *   circle <id> <x> <y> <vx> <vy>   for every circle, in cc_world_get_circles' order
 * where <bits> are the 16 hex digits of a double. The journal is what circlecollide.js wrote,
 * one call per line, every number as its bits, each call's result after "=":
 *   def MAX_CIRCLES MAX_SEGMENTS MODE RESTITUTION REST_SPEED ROLLING_DECEL MIX CALLBACKS
 *   init = STATUS | add_circle PX PY VX VY R M = ID | set_circle ID PX PY VX VY R M = R
 *   remove_circle ID = R | add_segment AX AY BX BY = ID | circle_restitution ID E = R
 *   circle_sensor ID = R | circle_category ID CATEGORY = R | segment_restitution ID E = R
 *   step DT = R
 * Each call does what demo/web/glue.c does for the page. A result that differs from the page's
 * is reported and makes the exit status 1; scripts/test.d/70-web.sh compares the printed state
 * with the page's. usage: web_replay JOURNAL */
#include "calls.h"

#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double bits(const char *s)
{
    uint64_t u = strtoull(s, NULL, 16);
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

static void put(double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    printf(" %016" PRIx64, u);
}

/* the page's plain-C calls (demo/web/calls.c) are linked in: the replay runs the same code; the
 * callbacks do nothing, as long as the page's do not change the world (they may not) */
void web_on_contact(const cc_contact_event *e, void *user)
{
    (void)e;
    (void)user;
}

void web_on_sensor(const cc_sensor_event *e, void *user)
{
    (void)e;
    (void)user;
}

#define MAX_TOKENS 16

int main(int argc, char **argv)
{
    static char line[4096];
    char *tok[MAX_TOKENS];
    int max_circles = 0;
    cc_world *w = NULL;
    void *memory = NULL;
    FILE *f;
    long lineno = 0, calls = 0;
    int bad = 0, i, n;

    if (argc != 2) {
        fprintf(stderr, "usage: %s JOURNAL\n", argv[0]);
        return 2;
    }
    f = fopen(argv[1], "r");
    if (f == NULL) {
        perror(argv[1]);
        return 2;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        int r = 0, expected = 0, has_result = 0;
        const char *op;
        cc_circle c;
        cc_segment s;
        ++lineno;
        n = 0;
        for (tok[n] = strtok(line, " \t\r\n"); tok[n] != NULL && n < MAX_TOKENS - 1;
             tok[++n] = strtok(NULL, " \t\r\n")) {
        }
        if (n == 0)
            continue;
        if (n >= 2 && strcmp(tok[n - 2], "=") == 0) {
            expected = atoi(tok[n - 1]);
            has_result = 1;
            n -= 2;
        }
        op = tok[0];
        if (strcmp(op, "def") == 0 && n == 9) {
            max_circles = atoi(tok[1]);
            web_def(max_circles, atoi(tok[2]), atoi(tok[3]), bits(tok[4]), bits(tok[5]), bits(tok[6]), atoi(tok[7]),
                    atoi(tok[8]));
            continue;
        } else if (strcmp(op, "init") == 0 && n == 1) {
            size_t bytes = web_world_size();
            free(memory);
            memory = bytes > 0 ? malloc(bytes + 15) : NULL; /* the world wants 16-byte alignment */
            w = memory != NULL ? web_world_init((void *)(((uintptr_t)memory + 15u) & ~(uintptr_t)15u), bytes) : NULL;
            r = memory != NULL ? web_status() : CC_ERR_MEMORY;
        } else if (w == NULL) {
            fprintf(stderr, "%s:%ld: %s before a world was made\n", argv[1], lineno, op);
            return 2;
        } else if ((strcmp(op, "add_circle") == 0 && n == 7) || (strcmp(op, "set_circle") == 0 && n == 8)) {
            int k = n - 6;
            c.pos.x = bits(tok[k]);
            c.pos.y = bits(tok[k + 1]);
            c.vel.x = bits(tok[k + 2]);
            c.vel.y = bits(tok[k + 3]);
            c.radius = bits(tok[k + 4]);
            c.mass = bits(tok[k + 5]);
            r = op[0] == 'a' ? cc_world_add_circle(w, &c) : cc_world_set_circle(w, atoi(tok[1]), &c);
        } else if (strcmp(op, "remove_circle") == 0 && n == 2) {
            r = cc_world_remove_circle(w, atoi(tok[1]));
        } else if (strcmp(op, "add_segment") == 0 && n == 5) {
            s.a.x = bits(tok[1]);
            s.a.y = bits(tok[2]);
            s.b.x = bits(tok[3]);
            s.b.y = bits(tok[4]);
            r = cc_world_add_segment(w, &s);
        } else if (strcmp(op, "circle_restitution") == 0 && n == 3) {
            r = web_circle_restitution(w, atoi(tok[1]), bits(tok[2]));
        } else if (strcmp(op, "circle_sensor") == 0 && n == 2) {
            r = web_circle_sensor(w, atoi(tok[1]));
        } else if (strcmp(op, "circle_category") == 0 && n == 3) {
            r = web_circle_category(w, atoi(tok[1]), (uint32_t)strtoul(tok[2], NULL, 10));
        } else if (strcmp(op, "segment_restitution") == 0 && n == 3) {
            r = web_segment_restitution(w, atoi(tok[1]), bits(tok[2]));
        } else if (strcmp(op, "step") == 0 && n == 2) {
            r = cc_world_step(w, bits(tok[1]));
        } else {
            fprintf(stderr, "%s:%ld: cannot read: %s (%d words)\n", argv[1], lineno, op, n);
            return 2;
        }
        ++calls;
        if (has_result && r != expected) {
            if (bad < 10)
                fprintf(stderr, "%s:%ld: %s returned %d here, %d in the page\n", argv[1], lineno, op, r,
                        expected);
            bad = 1;
        }
    }
    fclose(f);
    if (w == NULL) {
        fprintf(stderr, "%s: no world made\n", argv[1]);
        return 2;
    }
    {
        int cap = max_circles, count;
        int *ids = (int *)malloc(sizeof(int) * (size_t)(cap > 0 ? cap : 1));
        cc_circle *out = (cc_circle *)malloc(sizeof(cc_circle) * (size_t)(cap > 0 ? cap : 1));
        if (ids == NULL || out == NULL)
            return 2;
        count = cc_world_get_circles(w, ids, out, cap);
        printf("time");
        put(cc_world_time(w));
        printf("\nhash %016" PRIx64 "\n", cc_world_hash(w));
        for (i = 0; i < count; ++i) {
            printf("circle %d", ids[i]);
            put(out[i].pos.x);
            put(out[i].pos.y);
            put(out[i].vel.x);
            put(out[i].vel.y);
            printf("\n");
        }
        fprintf(stderr, "web_replay: %ld calls replayed, %d circles%s\n", calls, count,
                bad ? ", SOME RESULTS DIFFER" : "");
        free(ids);
        free(out);
    }
    free(memory);
    return bad;
}
