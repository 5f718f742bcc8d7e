/* Private to the library: the simultaneous-impact model. Resolves every contact of a cluster
 * (bodies touching or colliding at one instant) together, by Smith et al.'s generalized
 * reflections with generalized restitution (GR/GRR, "Reflections on Simultaneous Impact",
 * SIGGRAPH 2012). Pure: velocities in, velocities and impulses out, no positions, no
 * allocation (the caller hands in scratch memory). docs/SIMULTANEOUS.md explains the model,
 * the properties it keeps and gives up, and the tolerances. Never installed. */
#ifndef CC_WORLD_CLUSTER_H
#define CC_WORLD_CLUSTER_H

#include "circlecollide.h"

#include <stddef.h>

/* One body of the cluster. inv_mass = 0 is an immovable body (it keeps its velocity). */
typedef struct cc__cluster_body {
    cc_vec2 vel;     /* in: velocity before the impact; out: after */
    double inv_mass; /* finite, >= 0 */
} cc__cluster_body;

/* One contact: body a against body b, or against a static obstacle (a wall) when b = -1. */
typedef struct cc__cluster_contact {
    int a;          /* body index in [0, bodies) */
    int b;          /* body index in [0, bodies), != a, or -1 for a static obstacle */
    cc_vec2 normal; /* unit normal from a towards b (or towards the obstacle) */
    double impulse; /* out: total normal impulse applied here (mass * velocity, >= 0) */
} cc__cluster_contact;

/* What the solve did, for the world's statistics and for tests. */
typedef struct cc__cluster_report {
    int impulses;       /* contacts that received a positive impulse */
    int rounds;         /* GR rounds: simultaneous elastic solves over the approaching contacts */
    int capped;         /* 1: the GR round cap was reached; a plastic finish made the result
                           non-approaching (energy then decreases even at restitution 1) */
    int jammed;         /* 1: some contact still approaches: it can only be resolved by moving an
                           immovable body (e.g. squeezed between two converging obstacles) */
    double restitution; /* the restitution used: 0 when every approach was below rest_speed */
} cc__cluster_report;

/* Bytes of scratch memory cc__cluster_resolve needs for a cluster of this size (aligned like
 * malloc's memory), or 0 when the counts are negative or the size would overflow. Grows as
 * 4 * contacts^2: the solver keeps the packed L D L^T factor of its Delassus matrix. */
size_t cc__cluster_scratch_size(int bodies, int contacts);

/* Resolves the cluster with restitution e in [0, 1]; when no contact approaches faster than
 * rest_speed (>= 0), e = 0 is used (the world's remedy for inelastic collapse). Writes the new
 * velocities into bodies[].vel and each contact's impulse into contacts[].impulse, and fills
 * *report when it is not NULL. Afterwards no contact approaches by more than the rounding
 * tolerance (unless report->jammed). Returns CC_OK; CC_ERR_INVALID for bad input (NULL arrays
 * with counts > 0, an index out of range, a == b, a contact between two immovable bodies or an
 * immovable body and an obstacle, a normal that is not unit, a NaN or infinite velocity, e or
 * rest_speed out of range); CC_ERR_MEMORY when scratch is NULL or smaller than
 * cc__cluster_scratch_size(bodies, contacts). On error nothing is written. */
int cc__cluster_resolve(cc__cluster_body *bodies, int nbodies, cc__cluster_contact *contacts,
                        int ncontacts, double restitution, double rest_speed, void *scratch,
                        size_t scratch_bytes, cc__cluster_report *report);

#endif
