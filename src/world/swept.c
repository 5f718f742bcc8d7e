/* SWEPT mode: placeholder until written. */
#include "world_internal.h"
int cc__step_swept(cc_world *w, double dt) { return cc__step_exact(w, w->now + dt); }
