/* The simultaneous-impact model: generalized reflections (GR) with generalized restitution
 * (GRR), after Smith, Kaufman, Vouga, Tamstorf and Grinspun, "Reflections on Simultaneous
 * Impact" (SIGGRAPH 2012). See cluster.h for the contract and docs/SIMULTANEOUS.md for the
 * model's properties.
 *
 * Notation: v the stacked body velocities, M the mass matrix, N the contact normals (column k
 * pushes body b along +n_k and body a along -n_k), W = N^T M^-1 N the Delassus matrix, and
 * b = N^T v the normal relative velocities (b_k < 0: contact k approaches).
 *
 * The inelastic (plastic) projection onto a contact set S is the M-metric projection of v onto
 * the cone {u : N_S^T u >= 0}: v + M^-1 N_S lam with lam >= 0 solving the LCP
 *     w = b_S + W_SS lam >= 0,  lam >= 0,  lam . w = 0.
 * The projected velocity is unique even when W_SS is singular (a hex-packed rack has more
 * contacts than degrees of freedom), only the split of lam among redundant contacts is not.
 *
 * GR (restitution 1): repeat { S = contacts approaching now; v += 2 M^-1 N_S lam } until none
 * approaches. Each round is a reflection of v across the boundary of a convex cone in the
 * M-metric, so it keeps kinetic energy exactly; contacts that are merely touching are left out
 * of a round, which is what lets a Newton's cradle send out exactly one ball.
 * GRR (restitution e): the impulses (1 - e) * plastic(all contacts) + e * GR. Both parts are
 * non-approaching everywhere, so their convex combination is too; energy cannot grow (kinetic
 * energy is convex); and the solve ends after one plastic solve plus GR, which removes the
 * endless ping-pong that per-round restitution e < 1 shows in a cradle. */
#include "world/cluster.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* "Approaching" means b_k < -tol with tol = CC__CLUSTER_TOL_ULPS * DBL_EPSILON * (largest body
 * speed in the cluster): relative velocities carry a few ulps of rounding from the sums that
 * made them, and a contact approaching by less than that is touching. */
#define CC__CLUSTER_TOL_ULPS 256.0
/* A contact whose column is this close (relative) to the span of the contacts already in the
 * solve adds no new direction: it is redundant (a closed loop of contacts in a rack). */
#define CC__CLUSTER_PIVOT_TOL 1e-11

typedef struct cc__scratch {
    double *v;       /* 2 * nb: working velocities (x, y) */
    double *acc;     /* nc: accumulated GR impulses */
    double *plastic; /* nc: plastic impulses */
    double *b;       /* nc: relative normal velocities of the solve set */
    double *lam;     /* nc: LCP unknowns */
    double *z;       /* nc: LCP trial point */
    double *w;       /* nc: LCP residual */
    double *L;       /* nc (nc + 1) / 2: LDL^T factors of the passive block, packed rows */
    const cc__cluster_body *bodies;       /* the cluster, for the Delassus entries */
    const cc__cluster_contact *contacts;
    int *set;        /* nc: contact indices of the solve set */
    int *passive;    /* nc: positions (in the set) of the passive unknowns, in entry order */
    unsigned char *in_passive; /* nc */
    unsigned char *blocked;    /* nc: redundant or unresolvable in this solve */
} cc__scratch;

static size_t cc__align16(size_t n) { return (n + 15u) & ~(size_t)15u; }

size_t cc__cluster_scratch_size(int bodies, int contacts)
{
    size_t nb, nc, doubles, bytes;
    if (bodies < 0 || contacts < 0)
        return 0;
    nb = (size_t)bodies;
    nc = (size_t)contacts;
    /* nc (nc + 1) / 2 + 6 nc + 2 nb doubles, then 2 nc ints and 2 nc bytes */
    if (nc > 0 && nc > (SIZE_MAX / 64u) / nc)
        return 0;
    if (nb > SIZE_MAX / 64u)
        return 0;
    doubles = nc * (nc + 1u) / 2u + 6u * nc + 2u * nb;
    if (doubles > SIZE_MAX / 16u)
        return 0;
    bytes = cc__align16(doubles * sizeof(double)) + cc__align16(2u * nc * sizeof(int)) +
            cc__align16(2u * nc) + 16u;
    return bytes;
}

static void cc__scratch_carve(cc__scratch *s, void *memory, int nb, int nc)
{
    unsigned char *p = (unsigned char *)memory;
    size_t n = (size_t)nc, m = (size_t)nb;
    uintptr_t mis = (uintptr_t)p & 15u;
    if (mis != 0)
        p += 16u - mis; /* scratch_size reserves these 16 bytes */
    s->v = (double *)(void *)p;
    s->acc = s->v + 2u * m;
    s->plastic = s->acc + n;
    s->b = s->plastic + n;
    s->lam = s->b + n;
    s->z = s->lam + n;
    s->w = s->z + n;
    s->L = s->w + n;
    p += cc__align16((n * (n + 1u) / 2u + 6u * n + 2u * m) * sizeof(double));
    s->set = (int *)(void *)p;
    s->passive = s->set + n;
    p += cc__align16(2u * n * sizeof(int));
    s->in_passive = p;
    s->blocked = p + n;
}

/* ---- validation --------------------------------------------------------------------------- */

static int cc__finite(double x) { return x - x == 0.0; }

static int cc__input_ok(const cc__cluster_body *bodies, int nb, const cc__cluster_contact *contacts,
                        int nc, double e, double rest_speed)
{
    int i;
    if (nb < 0 || nc < 0 || (nb > 0 && bodies == NULL) || (nc > 0 && contacts == NULL))
        return 0;
    if (!(e >= 0.0 && e <= 1.0) || !(rest_speed >= 0.0))
        return 0;
    for (i = 0; i < nb; ++i) {
        const cc__cluster_body *q = &bodies[i];
        if (!cc__finite(q->vel.x) || !cc__finite(q->vel.y) || !cc__finite(q->inv_mass) ||
            !(q->inv_mass >= 0.0))
            return 0;
    }
    for (i = 0; i < nc; ++i) {
        const cc__cluster_contact *k = &contacts[i];
        double n2;
        if (k->a < 0 || k->a >= nb || k->b < -1 || k->b >= nb || k->a == k->b)
            return 0;
        if (!cc__finite(k->normal.x) || !cc__finite(k->normal.y))
            return 0;
        n2 = k->normal.x * k->normal.x + k->normal.y * k->normal.y;
        if (!(fabs(n2 - 1.0) <= 1e-9)) /* the world's normals are unit to a few ulps */
            return 0;
        if (bodies[k->a].inv_mass == 0.0 && (k->b < 0 || bodies[k->b].inv_mass == 0.0))
            return 0;
    }
    return 1;
}

/* ---- contact algebra ---------------------------------------------------------------------- */

/* n_k . (v_b - v_a) for the working velocities v; an obstacle does not move. */
static double cc__approach(const cc__cluster_contact *k, const double *v)
{
    double rx = -v[2 * k->a], ry = -v[2 * k->a + 1];
    if (k->b >= 0) {
        rx += v[2 * k->b];
        ry += v[2 * k->b + 1];
    }
    return k->normal.x * rx + k->normal.y * ry;
}

/* W_kl = (n_k . n_l) * sum over shared bodies x of (sign of x in k)(sign of x in l) / m_x. */
static double cc__delassus(const cc__cluster_body *bodies, const cc__cluster_contact *k,
                           const cc__cluster_contact *l)
{
    double s = 0.0;
    if (k->a == l->a)
        s += bodies[k->a].inv_mass;
    if (k->a == l->b)
        s -= bodies[k->a].inv_mass;
    if (k->b >= 0 && k->b == l->b)
        s += bodies[k->b].inv_mass;
    if (k->b >= 0 && k->b == l->a)
        s -= bodies[k->b].inv_mass;
    if (s == 0.0)
        return 0.0;
    return s * (k->normal.x * l->normal.x + k->normal.y * l->normal.y);
}

/* Entry (i, j) of the Delassus matrix of the solve set, computed when needed (an O(1) formula),
 * so that the scratch holds only the factors. */
static double cc__W(const cc__scratch *s, int i, int j)
{
    return cc__delassus(s->bodies, &s->contacts[s->set[i]], &s->contacts[s->set[j]]);
}

/* Packed lower triangle: row i starts at i (i + 1) / 2. */
#define CC__TRI(i, j) ((size_t)(i) * (size_t)((i) + 1) / 2u + (size_t)(j))

/* v += M^-1 n_k * impulse */
static void cc__push(const cc__cluster_body *bodies, const cc__cluster_contact *k, double impulse,
                     double *v)
{
    double ia = bodies[k->a].inv_mass * impulse;
    v[2 * k->a] -= ia * k->normal.x;
    v[2 * k->a + 1] -= ia * k->normal.y;
    if (k->b >= 0) {
        double ib = bodies[k->b].inv_mass * impulse;
        v[2 * k->b] += ib * k->normal.x;
        v[2 * k->b + 1] += ib * k->normal.y;
    }
}

static double cc__speed_scale(const double *v, int nb)
{
    double m = 0.0;
    int i;
    for (i = 0; i < 2 * nb; ++i) {
        double a = fabs(v[i]);
        if (a > m)
            m = a;
    }
    return m;
}

/* ---- the LCP: Lawson-Hanson's active-set method on the Delassus form ---------------------- */

/* Rows from..np-1 of the LDL^T factorization of the passive block W_PP (unit lower L in the
 * strict lower triangle, D on the diagonal; row-major, stride n); rows before `from` are kept:
 * row i depends only on the rows above it, so appending a contact costs one row and removing
 * one recomputes only the rows below it. No square roots: a lone contact gets z = -b / W with a
 * single rounding, as in the pair response. Returns 0 when a pivot is not clearly positive: the
 * column adds no direction the others do not span. */
static int cc__ldl_rows(const cc__scratch *s, const int *passive, int np, int from, double *L)
{
    int i, j, k;
    for (i = from; i < np; ++i) {
        double *Li = L + CC__TRI(i, 0);
        double w_ii = cc__W(s, passive[i], passive[i]), d = w_ii;
        for (j = 0; j < i; ++j) {
            const double *Lj = L + CC__TRI(j, 0);
            double v = cc__W(s, passive[i], passive[j]);
            for (k = 0; k < j; ++k)
                v -= Li[k] * Lj[k] * L[CC__TRI(k, k)];
            Li[j] = v / Lj[j];
            d -= Li[j] * Li[j] * Lj[j];
        }
        if (!(d > CC__CLUSTER_PIVOT_TOL * w_ii))
            return 0;
        Li[i] = d;
    }
    return 1;
}

/* z_P = -W_PP^-1 b_P with the factors; z elsewhere 0. */
static void cc__ldl_solve(const double *L, const int *passive, int np, const double *b, double *z, int m)
{
    int i, k;
    for (i = 0; i < m; ++i)
        z[i] = 0.0;
    for (i = 0; i < np; ++i) { /* L y = -b_P */
        double s = -b[passive[i]];
        for (k = 0; k < i; ++k)
            s -= L[CC__TRI(i, k)] * z[passive[k]];
        z[passive[i]] = s;
    }
    for (i = np - 1; i >= 0; --i) { /* D L^T x = y */
        double s = z[passive[i]] / L[CC__TRI(i, i)];
        for (k = i + 1; k < np; ++k)
            s -= L[CC__TRI(k, i)] * z[passive[k]];
        z[passive[i]] = s;
    }
}

/* Removes position r from the passive list and refactors the rows below it. Removing columns
 * from a positive definite block leaves it positive definite, so this cannot fail in exact
 * arithmetic; should rounding make it fail, the remaining rows are dropped too (returns the new
 * count, the unknowns dropped set to 0). */
static int cc__passive_remove(cc__scratch *s, int np, int r)
{
    int i;
    s->in_passive[s->passive[r]] = 0;
    for (i = r; i + 1 < np; ++i)
        s->passive[i] = s->passive[i + 1];
    --np;
    if (!cc__ldl_rows(s, s->passive, np, r, s->L)) {
        for (i = r; i < np; ++i) {
            s->in_passive[s->passive[i]] = 0;
            s->lam[s->passive[i]] = 0.0;
        }
        np = r;
    }
    return np;
}

/* Solves the LCP of the m contacts in s->set (W in s->W with stride n = m, b in s->b) into
 * s->lam[0..m). Afterwards every w_k = b_k + (W lam)_k >= -tol unless a blocked contact stays
 * approaching (returns 1: jammed) or the pivot cap is reached (returns 2). */
static int cc__lcp(cc__scratch *s, int m, double tol)
{
    int np = 0, outer, i, k, status = 0;
    double *lam = s->lam, *z = s->z, *w = s->w;
    for (i = 0; i < m; ++i) {
        s->in_passive[i] = 0;
        s->blocked[i] = 0;
        lam[i] = 0.0;
    }
    for (outer = 0;; ++outer) {
        int j = -1;
        double most = -tol;
        for (i = 0; i < m; ++i) {
            double g = s->b[i];
            for (k = 0; k < np; ++k)
                g += cc__W(s, i, s->passive[k]) * lam[s->passive[k]];
            w[i] = g;
        }
        for (i = 0; i < m; ++i)
            if (!s->in_passive[i] && !s->blocked[i] && w[i] < most) {
                most = w[i];
                j = i;
            }
        if (j < 0)
            break;
        if (outer >= 3 * m + 10) {
            status = 2;
            break;
        }
        s->passive[np++] = j;
        s->in_passive[j] = 1;
        if (!cc__ldl_rows(s, s->passive, np, np - 1, s->L)) {
            s->in_passive[j] = 0;
            --np;
            s->blocked[j] = 1; /* redundant: the others already span its direction */
            continue;
        }
        for (;;) {
            double alpha = 1.0;
            int all_positive = 1, first = -1;
            cc__ldl_solve(s->L, s->passive, np, s->b, z, m);
            if (s->in_passive[j] && lam[j] == 0.0 && !(z[j] > 0.0)) {
                /* in exact arithmetic an entering contact always gets a positive impulse;
                 * rounding can deny it that, and then it must not enter again */
                for (k = 0; s->passive[k] != j; ++k) {
                }
                np = cc__passive_remove(s, np, k);
                s->blocked[j] = 1;
                break;
            }
            for (k = 0; k < np; ++k)
                if (!(z[s->passive[k]] > 0.0))
                    all_positive = 0;
            if (all_positive) {
                for (k = 0; k < np; ++k)
                    lam[s->passive[k]] = z[s->passive[k]];
                break;
            }
            /* step from lam towards z until the first passive unknown reaches zero */
            for (k = 0; k < np; ++k) {
                int p = s->passive[k];
                if (!(z[p] > 0.0)) {
                    double t = lam[p] > 0.0 ? lam[p] / (lam[p] - z[p]) : 0.0;
                    if (first < 0 || t < alpha) {
                        alpha = t;
                        first = p;
                    }
                }
            }
            for (k = 0; k < np; ++k) {
                int p = s->passive[k];
                lam[p] += alpha * (z[p] - lam[p]);
            }
            lam[first] = 0.0; /* exactly, whatever the rounding of the step */
            /* drop the unknowns that reached zero (at least the one that set alpha) */
            for (k = 0; k < np;) {
                if (!(lam[s->passive[k]] > 0.0)) {
                    lam[s->passive[k]] = 0.0;
                    np = cc__passive_remove(s, np, k);
                } else {
                    ++k;
                }
            }
            if (np == 0)
                break;
        }
    }
    if (status == 0) {
        for (i = 0; i < m; ++i)
            if (s->blocked[i] && w[i] < -tol)
                status = 1;
    }
    return status;
}

/* Plastic projection of the working velocities s->v onto the contacts in s->set[0..m): adds
 * scale * lam to impulses[] and scale * M^-1 N lam to s->v (when apply_v). */
static int cc__project(const cc__cluster_body *bodies, const cc__cluster_contact *contacts,
                       cc__scratch *s, int m, double tol, double scale, double *impulses,
                       int apply_v)
{
    int i, status;
    for (i = 0; i < m; ++i) {
        const cc__cluster_contact *k = &contacts[s->set[i]];
        s->b[i] = cc__approach(k, s->v);
    }
    status = cc__lcp(s, m, tol);
    for (i = 0; i < m; ++i) {
        if (s->lam[i] > 0.0) {
            impulses[s->set[i]] += scale * s->lam[i];
            if (apply_v)
                cc__push(bodies, &contacts[s->set[i]], scale * s->lam[i], s->v);
        }
    }
    return status;
}

static void cc__load_velocities(const cc__cluster_body *bodies, int nb, double *v)
{
    int i;
    for (i = 0; i < nb; ++i) {
        v[2 * i] = bodies[i].vel.x;
        v[2 * i + 1] = bodies[i].vel.y;
    }
}

/* ---- the model ---------------------------------------------------------------------------- */

int cc__cluster_resolve(cc__cluster_body *bodies, int nbodies, cc__cluster_contact *contacts,
                        int ncontacts, double restitution, double rest_speed, void *scratch,
                        size_t scratch_bytes, cc__cluster_report *report)
{
    cc__scratch s;
    cc__cluster_report rep;
    double e = restitution, fastest = 0.0, tol;
    int i, k, m, cap, jammed = 0;
    size_t need;
    if (!cc__input_ok(bodies, nbodies, contacts, ncontacts, restitution, rest_speed))
        return CC_ERR_INVALID;
    need = cc__cluster_scratch_size(nbodies, ncontacts);
    if (scratch == NULL || need == 0 || scratch_bytes < need)
        return CC_ERR_MEMORY;
    cc__scratch_carve(&s, scratch, nbodies, ncontacts);
    s.bodies = bodies;
    s.contacts = contacts;
    memset(&rep, 0, sizeof rep);

    cc__load_velocities(bodies, nbodies, s.v);
    for (k = 0; k < ncontacts; ++k) {
        double a = -cc__approach(&contacts[k], s.v);
        if (a > fastest)
            fastest = a;
        s.acc[k] = 0.0;
        s.plastic[k] = 0.0;
    }
    if (fastest < rest_speed)
        e = 0.0; /* the world's rule for slow approaches, applied to the cluster as a whole */
    rep.restitution = e;

    /* GR at restitution 1: rounds of simultaneous reflection over the approaching contacts */
    cap = 64 + 8 * ncontacts;
    if (e > 0.0) {
        for (;;) {
            tol = CC__CLUSTER_TOL_ULPS * DBL_EPSILON * cc__speed_scale(s.v, nbodies);
            for (m = 0, k = 0; k < ncontacts; ++k)
                if (cc__approach(&contacts[k], s.v) < -tol)
                    s.set[m++] = k;
            if (m == 0)
                break;
            if (rep.rounds >= cap) {
                /* finish with one plastic projection over every contact: non-approaching,
                 * symmetric, momentum-conserving, but it dissipates */
                rep.capped = 1;
                for (m = 0; m < ncontacts; ++m)
                    s.set[m] = m;
                if (cc__project(bodies, contacts, &s, m, tol, 1.0, s.acc, 1) != 0)
                    jammed = 1;
                break;
            }
            if (cc__project(bodies, contacts, &s, m, tol, 2.0, s.acc, 1) != 0)
                jammed = 1;
            rep.rounds++;
        }
    }
    /* the plastic part, from the velocities before the impact, over every contact */
    if (e < 1.0) {
        cc__load_velocities(bodies, nbodies, s.v);
        tol = CC__CLUSTER_TOL_ULPS * DBL_EPSILON * cc__speed_scale(s.v, nbodies);
        for (m = 0; m < ncontacts; ++m)
            s.set[m] = m;
        if (cc__project(bodies, contacts, &s, m, tol, 1.0, s.plastic, 0) != 0)
            jammed = 1;
    }

    /* impulses (1 - e) plastic + e GR, and the velocities they give from the initial ones */
    cc__load_velocities(bodies, nbodies, s.v);
    for (k = 0; k < ncontacts; ++k) {
        double j = (e == 1.0) ? s.acc[k] : (e == 0.0) ? s.plastic[k]
                                                     : (1.0 - e) * s.plastic[k] + e * s.acc[k];
        contacts[k].impulse = j;
        if (j > 0.0) {
            cc__push(bodies, &contacts[k], j, s.v);
            rep.impulses++;
        }
    }
    for (i = 0; i < nbodies; ++i) {
        if (bodies[i].inv_mass == 0.0)
            continue; /* immovable: bit-for-bit unchanged */
        bodies[i].vel.x = s.v[2 * i];
        bodies[i].vel.y = s.v[2 * i + 1];
    }
    rep.jammed = jammed;
    if (report != NULL)
        *report = rep;
    return CC_OK;
}
