/*
 * wavyadhesion.h - C interface of the wavyadhesion library: adhesive contact of a
 * wavy (sinusoidal) elastic surface against a flat (Westergaard, JKR,
 * double-Westergaard and Maugis-Dugdale models), in dimensionless form.
 *
 * Copyright 2026, wavyadhesion developers. SPDX-License-Identifier: GPL-3.0-or-later
 *
 * Conventions (see doc/c-api.md):
 * - loads P* = mean traction / p*, p* = pi E* Delta / L (negative = tensile);
 *   widths a* = a/L and c* = c/L in [0, 1/2]; parameters alpha in
 *   [WA_ALPHA_MIN, WA_ALPHA_MAX] and mu = 0 or in [WA_MU_MIN, WA_MU_MAX] (the supported
 *   domain, see doc/theory.md; NaN, infinite and other values give WA_INVALID_ARGUMENT
 *   with a message stating this range);
 * - one function per capability: every function that takes pointers returns an int
 *   status (WA_OK = 0), writes its results through the pointers and ends with
 *   `char *message, int message_capacity`: the reason for a failure (naming the argument
 *   and its valid range), truncated to message_capacity - 1 bytes and NUL-terminated,
 *   "" on WA_OK; NULL or a capacity <= 0 copies nothing (256 bytes never truncate);
 * - optional outputs (the mean gap gbar, a sweep's row_status) are pointers that may be
 *   NULL: then they are neither computed nor written;
 * - arrays are caller-allocated with an explicit capacity; nothing is allocated for the
 *   caller to free;
 * - NULL result pointers (other than the optional ones) give WA_INVALID_ARGUMENT (never
 *   a crash);
 * - on failure each function writes the values it states below (NaN, 0, -1) through
 *   every result pointer that is not NULL, whatever the failure (an invalid model or
 *   argument, another pointer being NULL, a numerical failure); result arrays are not
 *   written on failure (those of wa_critical_sweep excepted);
 * - WA_CAPACITY_TOO_SMALL is returned only by the functions with a `capacity` argument
 *   and only when the count they return exceeds it;
 * - every function is thread safe (no global state);
 * - the 0.2 names (_msg twins, _gap variants, wa_critical_sweep_status,
 *   wa_adhesion_map_control) are forwards in the marked block at the end, removed in 0.4.
 * Link with: -lwavyadhesion -lgfortran -lgsl -lgslcblas -lm; against the static library
 *   add -lfftw3_threads -lfftw3 (or take them all from pkg-config --static --libs
 *   wavyadhesion).
 */
#pragma once

#ifdef __cplusplus
extern "C" {
#endif

/* Models (equal to model_westergaard, model_jkr, model_dw, model_md in Fortran). */
#define WA_MODEL_WESTERGAARD 0
#define WA_MODEL_JKR 1
#define WA_MODEL_DW 2
#define WA_MODEL_MD 3
/* The smooth (Lennard-Jones) model: the code of the command line's `--model lj`; its
   functions are wa_lj_cycle, wa_lj_trace and wa_lj_profile (the functions taking a model
   argument accept 0-3 only). */
#define WA_MODEL_LJ 4

/* The supported parameter domain (alpha_min, alpha_max, mu_min, mu_max in the Fortran
   module wa_params): alpha in [WA_ALPHA_MIN, WA_ALPHA_MAX], mu = 0 or in
   [WA_MU_MIN, WA_MU_MAX]. */
#define WA_ALPHA_MIN 1e-12
#define WA_ALPHA_MAX 1e12
#define WA_MU_MIN 1e-100
#define WA_MU_MAX 1e100

/* Status codes (equal to the wa_* constants of the Fortran module wa_status). */
#define WA_OK 0
#define WA_INVALID_ARGUMENT 1   /* an argument is NaN, infinite, out of range or NULL */
#define WA_NO_SOLUTION 2        /* the equations have no solution of the kind asked for */
#define WA_NOT_CONVERGED 3      /* an iteration did not reach its tolerance */
#define WA_CAPACITY_TOO_SMALL 4 /* an array is too small: only what fits was written */
#define WA_NUMERICAL_ERROR 5    /* a numerical building block (GSL, quadrature) failed */

/* Zone cases of a state (zone_inside, zone_whole_period, zone_full_contact). */
#define WA_ZONE_NO_CONTACT 0    /* MD only: a* = 0, a Dugdale zone |x*| < c* and no contact
                                   (traced branches: the pieces ahead of the contact curve) */
#define WA_ZONE_INSIDE 1        /* a* < c* < 1/2 */
#define WA_ZONE_WHOLE_PERIOD 2  /* a* < c* = 1/2 */
#define WA_ZONE_FULL_CONTACT 3  /* a* = c* = 1/2 */

/* Event codes of branch points and load-path events (event_* in the Fortran module
   wa_branch; the same codes as the command line's `event` column). */
#define WA_EVENT_NONE 0                 /* an ordinary point */
#define WA_EVENT_FOLD 1                 /* a fold: d(P*)/d(a*) = 0 */
#define WA_EVENT_SWITCH 2               /* a zone-case switch: c* reaches or leaves 1/2 */
#define WA_EVENT_JUMP_START 3           /* a jump at constant load starts here */
#define WA_EVENT_JUMP_END 4             /* ... and lands here */
#define WA_EVENT_FULL_CONTACT_REACHED 5 /* full contact reached (load P_fc*) */
#define WA_EVENT_FULL_CONTACT_LEFT 6    /* full contact left on unloading */
#define WA_EVENT_PULL_OFF 7             /* contact lost (load P_pf*) */
#define WA_EVENT_BRANCH_END 8           /* first and last point of a branch */
#define WA_EVENT_A_TURN 9               /* a* turns back (two case-1 roots merge): not a
                                           fold; stability does not change there */

/* Stages of a load path (stage_loading, stage_unloading in wa_loadpath). */
#define WA_STAGE_LOADING 1      /* from separation at P* = 0 up to full contact */
#define WA_STAGE_UNLOADING 2    /* from full contact down to pull-off */

/* How full contact is reached / contact is lost (mechanism_* in wa_loadpath). */
#define WA_MECHANISM_GRADUAL 0    /* along a stable piece of the branch, no jump */
#define WA_MECHANISM_JUMP_CASE1 1 /* a jump leaving a zone-case-1 state (a fold) */
#define WA_MECHANISM_JUMP_CASE2 2 /* a jump leaving a zone-case-2 state (c* = 1/2) */
#define WA_MECHANISM_SNAP 3       /* full contact only: snap from separation at P* = 0 */

/* Boundaries of the adhesion map (wa_adhesion_map's control; map_control_* in wa_map)
   and the gap-control mechanisms its codes 3xx, 4xx combine. */
#define WA_MAP_CONTROL_LOAD 1
#define WA_MAP_CONTROL_GAP 2
#define WA_MAP_CONTROL_BOTH 3
#define WA_GAP_MECH_JUMP_CONTACT 1
#define WA_GAP_MECH_INNER_JUMPS 2

/* Stages of a gap path (gap_stage_approach, gap_stage_retraction in wa_gappath). */
#define WA_STAGE_APPROACH 1    /* gbar* falling from far apart to full contact */
#define WA_STAGE_RETRACTION 2  /* gbar* rising from full contact to far apart */

/* Event codes of a gap path (gap_event_* in wa_gappath; the `event` column of
   `wavyadhesion path --control gap`; 3-6 mean what WA_EVENT_3-6 mean). */
#define WA_GAP_EVENT_JUMP_START 3             /* a jump at constant gbar* starts here */
#define WA_GAP_EVENT_JUMP_END 4               /* ... and lands here */
#define WA_GAP_EVENT_FULL_CONTACT_REACHED 5   /* full contact reached (gbar* = 0) */
#define WA_GAP_EVENT_FULL_CONTACT_LEFT 6      /* full contact left on retraction */
#define WA_GAP_EVENT_TOUCH 10                 /* first interaction on approach (P* = 0) */
#define WA_GAP_EVENT_CONTACT_MADE 11          /* MD: the Dugdale zone's state meets the
                                                 contact curve on approach */
#define WA_GAP_EVENT_CONTACT_LOST 12          /* contact lost on retraction (a* -> 0) */
#define WA_GAP_EVENT_INTERACTION_LOST 13      /* P* = 0 beyond this gbar* */

/* Critical values under gap control: indices into the values[] of wa_gap_critical
   (the order of gap_critical_values in wa_gapcritical and of `wavyadhesion critical
   --control gap`). A jump under gap control keeps gbar*: the jump-in starts and lands at
   g_touch. */
#define WA_GAP_CRITICAL_COUNT 10
#define WA_GAP_CRITICAL_G_TOUCH 0            /* approach: gbar* of the first interaction */
#define WA_GAP_CRITICAL_P_JUMP_IN 1          /* P* where the approach lands when it jumps
                                                at g_touch (0: no jump) */
#define WA_GAP_CRITICAL_A_JUMP_IN 2          /* a* there (0: no jump, or MD landing on
                                                the states without contact) */
#define WA_GAP_CRITICAL_G_CONTACT 3          /* gbar* where contact is first made */
#define WA_GAP_CRITICAL_P_MIN 4              /* retraction: the most tensile load (equal
                                                to P_pf of wa_critical_forces in every case
                                                tested; JKR: -INFINITY) */
#define WA_GAP_CRITICAL_G_P_MIN 5            /* its gbar* (JKR: 0) */
#define WA_GAP_CRITICAL_A_P_MIN 6            /* its a* (JKR: 1/2) */
#define WA_GAP_CRITICAL_G_CONTACT_LOST 7     /* gbar* where contact is lost for good */
#define WA_GAP_CRITICAL_P_CONTACT_LOST 8     /* P* of the last state with contact */
#define WA_GAP_CRITICAL_G_INTERACTION_LOST 9 /* gbar* beyond which P* = 0 */

/* Westergaard load P* = sin^2(pi a*); NaN when a_star is outside [0, 1/2] or NaN. */
double wa_westergaard_load(double a_star);

/* JKR load P* = sin^2(pi a*) - alpha sqrt(tan(pi a*)) (Johnson 1995) for any finite
   alpha >= 0 (alpha = 0: the Westergaard load); -Infinity at a* = 1/2 when alpha > 0
   (and where alpha sqrt(tan(pi a*)) overflows); NaN when alpha is NaN, negative or
   infinite, or a_star is NaN or outside [0, 1/2]. */
double wa_jkr_load(double alpha, double a_star);

/* Short fixed text of a status code: a static NUL-terminated string, never NULL
   ("unknown status" for codes the library does not return). Do not free it. */
const char *wa_status_message(int status);

/* Version of the library, e.g. "0.2.0" (the same as the Fortran constant wa_version,
   Python's wavyadhesion.__version__ and `wavyadhesion --version`): a static
   NUL-terminated string, never NULL. Do not free it. */
const char *wa_version(void);

/* Principal equilibrium of `model` at a_star: c*, P* and zone case (DW, MD: the case-1
   state with the smallest c*, else the case-2 state; Westergaard, JKR: c* = a*, zone
   case 1, 3 at a* = 1/2; JKR at a* = 1/2: P* = -INFINITY), and, when gbar is not NULL,
   its mean gap gbar* = gbar/Delta (mean of the gap h over one period; 0 in full contact,
   1 for the undeformed wave touching at its crest; finite and >= 0 on WA_OK; where it is
   not defined, DW at a* = 0, the call fails with WA_NO_SOLUTION). On WA_OK c* is in
   [a*, 1/2] and P* is finite (JKR at 1/2 excepted). On any failure *c_star = *P_star =
   *gbar = NaN and *zone_case = 0 (each one that is not NULL). Never
   WA_CAPACITY_TOO_SMALL. */
int wa_equilibrium(int model, double alpha, double mu, double a_star,
                   double *c_star, double *P_star, int *zone_case, double *gbar,
                   char *message, int message_capacity);

/* Every equilibrium at a_star, case-1 states by increasing c*, then the case-2 state,
   and each one's mean gap in gbar[] when gbar is not NULL. *n_roots receives the total.
   When it exceeds `capacity` the first `capacity` states are written, nothing beyond,
   and WA_CAPACITY_TOO_SMALL is returned (capacity 0 with NULL arrays asks for the
   count). On any other failure *n_roots = 0 (when n_roots is not NULL) and the arrays
   are not written. */
int wa_roots(int model, double alpha, double mu, double a_star, int capacity,
             double *c_star, double *P_star, int *zone_case, double *gbar, int *n_roots,
             char *message, int message_capacity);

/* The equilibrium branch P*(a*), c*(a*) of `model` over 0 < a* <= 1/2, traced by
   pseudo-arclength continuation (DW, MD) or sampled from the closed form (Westergaard,
   JKR), in the order of the curve (not necessarily of a*), with every fold and zone-case
   switch as a point of its own (event[] = WA_EVENT_FOLD, WA_EVENT_SWITCH), and every point
   where a* turns back (MD: WA_EVENT_A_TURN; P* is not extremal there). The curve can
   come in pieces (DW, MD: a piece that returns to a* -> 0, then the one that reaches
   a* = 1/2; MD with mu > 0 begins with its states without contact, zone case
   WA_ZONE_NO_CONTACT, a* = 0, c* the Dugdale zone half-width, from the first interaction
   c* = 0 to where they join the a* -> 0 end of the contact curve; they are never stable
   under load control): each piece starts and ends with a WA_EVENT_BRANCH_END point, so the first
   and the last point are WA_EVENT_BRANCH_END, the last at a* = 1/2 (JKR: 1/2 - 1e-9,
   where P* is still finite), and a branch of k pieces has 2 (k - 1) more BRANCH_END
   points inside, in pairs at consecutive indices (the end of one piece, the start of
   the next). stable[] is 1 where the state is stable under load control, 0 elsewhere
   and at folds: on case 2 (c* = 1/2) where d(P*)/d(a*) > 0; on case 1 stability changes
   only at extrema of P* along the curve (folds, corner extrema), not at a*-turns, so a
   piece that returns after an a*-turn with P* rising as a* falls is unstable
   (doc/theory.md, "Stability under load control"). gbar[] (NULL: not computed)
   receives each point's mean gap. *n_points receives the number of points. When it
   exceeds `capacity` the first `capacity` points are written, nothing beyond, and
   WA_CAPACITY_TOO_SMALL is returned (capacity 0 with NULL arrays asks for the count; the
   branch is traced either way, so allocate generously: a few hundred points are usual).
   On any other failure *n_points = 0 (when n_points is not NULL) and the arrays are not
   written. */
int wa_trace_branch(int model, double alpha, double mu, int capacity,
                    double *a_star, double *c_star, double *P_star, int *zone_case,
                    int *stable, int *event, double *gbar, int *n_points,
                    char *message, int message_capacity);

/* Profile of one state: traction[i] = p/p* (positive = compressive) and gap[i] = h/Delta
   at x_star[i], i < n (x* = x/L, any finite value: period 1, crest at x* = 0). The state
   is the one at a_star whose c* is nearest c_star among the roots of wa_roots; it must
   lie within 1e-6 of c_star (Westergaard, JKR: c* = a*). MD at a_star = 0: the state
   without contact whose Dugdale zone |x*| < c_star pulls the crest (c_star < 1/2).
   On WA_OK every gap is finite and >= 0 (0 on the contact; MD: the Dugdale opening at
   |x*| = c*) and every traction finite, except JKR's -INFINITY exactly at |x*| = a*
   (folded into [0, 1/2] by |x* - round(x*)|). WA_INVALID_ARGUMENT: model, alpha, mu,
   a_star or c_star (in [0, 1/2]) invalid, n < 0, an array NULL while n > 0, or an x_star
   not finite. WA_NO_SOLUTION: no state at a_star has that c* (the message gives the
   nearest), MD at a_star = 0 with no no-contact state at c_star (the crest would touch)
   or c_star = 1/2 (not one state), DW at a_star = 0, JKR at a_star = 1/2 (full contact
   at any load). n = 0 only identifies the state. On any failure, when n > 0, every
   element of traction and gap (each that is not NULL) is NaN. */
int wa_profile(int model, double alpha, double mu, double a_star, double c_star, int n,
               const double *x_star, double *traction, double *gap, char *message,
               int message_capacity);

/* Critical forces under load control: *P_fc receives the load at which full contact is
   first reached on loading from separation at P* = 0, *P_pf the pull-off load on
   unloading from full contact (JKR: -INFINITY, full contact never releases); both finite
   otherwise. On failure both are NaN (each one that is not NULL). Never
   WA_CAPACITY_TOO_SMALL. */
int wa_critical_forces(int model, double alpha, double mu, double *P_fc, double *P_pf,
                       char *message, int message_capacity);

/* The events of load-controlled loading (stage WA_STAGE_LOADING: jump-in at P* = 0,
   jumps, full contact reached) and unloading (WA_STAGE_UNLOADING: full contact left,
   jumps, pull-off), in order, with *P_fc and *P_pf as wa_critical_forces gives them.
   *n_events receives the number of events (at most 64). When it exceeds `capacity` the
   first `capacity` events are written, nothing beyond, *P_fc and *P_pf too, and
   WA_CAPACITY_TOO_SMALL is returned. On any other failure *n_events = 0 and *P_fc =
   *P_pf = NaN (each one that is not NULL) and the arrays are not written. */
int wa_load_path(int model, double alpha, double mu, int capacity,
                 int *stage, int *event, double *a_star, double *c_star, double *P_star,
                 int *n_events, double *P_fc, double *P_pf,
                 char *message, int message_capacity);

/* P_fc*, P_pf* and their mechanisms (WA_MECHANISM_*) for one alpha and n_mu values of
   mu (the arrays have n_mu elements; they may be NULL when n_mu is 0). Every argument
   (every mu) is validated before any work: on an invalid one (WA_INVALID_ARGUMENT), when
   n_mu > 0, every element of each output array that is not NULL is NaN (mechanisms -1).
   A mu whose load path fails does not stop the sweep: its row gets NaN forces and
   mechanisms -1, every other row is written, and the status of the first failing row is
   returned (its message names that mu and the number of failing rows). row_status[i]
   (NULL: not written) receives the status of row i: WA_OK where its forces were
   computed, else the status of its failure (on an invalid argument, that status in every
   row). Never WA_CAPACITY_TOO_SMALL. */
int wa_critical_sweep(int model, double alpha, int n_mu, const double *mu,
                      double *P_fc, double *P_pf, int *fc_mechanism, int *pf_mechanism,
                      int *row_status, char *message, int message_capacity);

/* The adhesion map of the (alpha, mu) plane (Fortran adhesion_map, module wa_map):
   the boundary points where a mechanism changes, located to 2e-9 relative in mu over
   [mu_lo, mu_hi] (a discovery scan of n_mu log-spaced mu, n_mu in [2, 100000]; 0.2 used
   60), for model WA_MODEL_DW or WA_MODEL_MD and the n_alpha strictly increasing values
   alpha[] (each in [WA_ALPHA_MIN, WA_ALPHA_MAX]). Points come curve after curve, each
   curve in increasing alpha (it may add points between the given alpha, where it starts
   or ends). boundary_code[i] = 100*which + 10*(mechanism below) + (mechanism above) in
   mu. control WA_MAP_CONTROL_LOAD: which 1 full contact, 2 pull-off, mechanisms
   WA_MECHANISM_*: e.g. 101 full contact: gradual -> jump case 1, 103 full contact:
   gradual -> snap at P=0, 113 full contact: jump case 1 -> snap, 201 pull-off: gradual
   -> jump case 1, 202 pull-off: gradual -> jump case 2, 212 pull-off: jump case 1 ->
   jump case 2 (and the reverses, e.g. 210, 221). WA_MAP_CONTROL_GAP (gap control only):
   which 3 approach, 4 retraction, mechanisms sums of WA_GAP_MECH_JUMP_CONTACT (contact
   made / lost by a jump) and WA_GAP_MECH_INNER_JUMPS (jumps between states with
   contact), e.g. 401 gap retraction: gradual -> jump-out, 323 gap approach:
   gradual+inner jumps -> jump-in+inner jumps. WA_MAP_CONTROL_BOTH: both.
   *n_out receives the number of points; when it exceeds capacity, the first capacity
   points are written and WA_CAPACITY_TOO_SMALL is returned. On any other failure
   (WA_INVALID_ARGUMENT: another model or control, n_alpha outside [1, 100000], alpha not
   increasing, mu_lo >= mu_hi, n_mu outside [2, 100000], NULL pointers) *n_out = 0 when
   n_out is not NULL and the arrays are not written. Load control takes about 1 s (DW)
   to 10 s (MD) per 100 alpha at n_mu = 60; gap control about as much again for DW and
   5-10 times as much for MD. */
int wa_adhesion_map(int model, int control, int n_alpha, const double *alpha, double mu_lo,
                    double mu_hi, int n_mu, int capacity, int *boundary_code,
                    double *alpha_out, double *mu_out, int *n_out,
                    char *message, int message_capacity);

/* Gap (mean-gap) control (doc/c-api.md, "Gap control"): approach from far apart to full
   contact and retraction back, with gbar* imposed; jumps keep gbar*. */

/* The events of the gap-controlled approach (stage WA_STAGE_APPROACH) and retraction
   (WA_STAGE_RETRACTION), in order: stage, event (WA_GAP_EVENT_*), zone case, a*, c*, P*
   and gbar* of each (a jump's start and end share gbar*; events on the P* = 0 states
   far apart have a* = c* = P* = 0 and zone case WA_ZONE_NO_CONTACT). *W_star receives
   the energy lost per cycle W* = -oint P* dgbar* (units p* Delta; >= 0), *W_fraction
   W* / (pi alpha^2/2), *g_touch the gbar* of the first interaction (1, except for MD).
   *n_events receives the number of events (at most 64). When it exceeds `capacity` the
   first `capacity` events are written, nothing beyond, the three scalars too, and
   WA_CAPACITY_TOO_SMALL is returned (capacity 0 with NULL arrays asks for the count).
   On any other failure *n_events = 0 and *W_star = *W_fraction = *g_touch = NaN (each
   one that is not NULL) and the arrays are not written. */
int wa_gap_path(int model, double alpha, double mu, int capacity,
                int *stage, int *event, int *zone_case, double *a_star, double *c_star,
                double *P_star, double *gbar, int *n_events,
                double *W_star, double *W_fraction, double *g_touch,
                char *message, int message_capacity);

/* The gap law at n mean gaps gbar[i] (each finite and >= 0): P* after approaching from
   far apart (P_approach) and after retracting from full contact (P_retract), and the
   slopes dP* / dgbar* (P* = 0 and slope 0 where the surfaces do not interact; at gbar* = 0,
   full contact, P* is the full-contact load and the slopes are -INFINITY). n = 0 (NULL
   arrays allowed) only checks the arguments and the cycle. WA_INVALID_ARGUMENT: model,
   alpha, mu or a gbar[i] invalid (the message names gbar[i]), n < 0, an array NULL while
   n > 0. On any failure, when n > 0, every element of each output array that is not NULL
   is NaN. Never WA_CAPACITY_TOO_SMALL. */
int wa_gap_law(int model, double alpha, double mu, int n, const double *gbar,
               double *P_approach, double *P_retract, double *dPdg_approach,
               double *dPdg_retract, char *message, int message_capacity);

/* values[WA_GAP_CRITICAL_COUNT] receives the critical values under gap control (indices
   WA_GAP_CRITICAL_*); all finite except P_MIN of JKR (-INFINITY). On any failure every
   element of values (when it is not NULL) is NaN; NULL values gives WA_INVALID_ARGUMENT.
   Never WA_CAPACITY_TOO_SMALL. */
int wa_gap_critical(int model, double alpha, double mu, double *values, char *message,
                    int message_capacity);

/* Smooth adhesion (the self-consistent Lennard-Jones 3-9 law, doc/theory.md "Smooth
   adhesion"): the same work of adhesion as DW/MD at (alpha, mu), mu > 0, and the range
   eps = the MD opening, eps/Delta = (4 alpha^4)^(1/3)/mu. n is the grid points per period
   (0: automatic); profile NULL is the sinusoid 1 - cos 2 pi x*, else n_profile >= 4
   heights over Delta at x* = j/n_profile (n_profile is ignored when profile is NULL).
   A grid cap exceeded (automatic grid > 2048, n > 16384 / 8192 / 2048 uneven) is
   WA_INVALID_ARGUMENT, and so is a law whose range eps/Delta exceeds 1e5 (mu too small
   for alpha: the far gaps' rounding would swamp the profile). */

/* The load- and gap-controlled cycle: P_fc*, P_pf*, the snap load (the last jump on
   loading), W* (over p* Delta) and (NULL allowed) P_fc_peak*, the load at which b* first
   reaches 1/2 on loading (the full-contact load comparable with DW's and MD's P_fc*),
   with errors[5] (NULL allowed) = |value at N - value at N/2| of the same five and
   *n_used (NULL allowed) = N. n: 0 or a multiple of 4, >= 16 (N/2 is solved too). On any
   failure the five values and errors are NaN and *n_used = 0 (each one not NULL). Never
   WA_CAPACITY_TOO_SMALL. */
int wa_lj_cycle(double alpha, double mu, int n, int n_profile, const double *profile,
                double *P_fc, double *P_pf, double *P_snap, double *W_star,
                double *P_fc_peak, double *errors, int *n_used, char *message,
                int message_capacity);

/* The equilibrium curve from far apart to full contact: P*, gbar* (over Delta), a*, b*
   of each point, and (each NULL allowed) its stability under load and gap control (1/0)
   and event code (0 none, 1 fold of P*, 14 fold of gbar*, 5 a* reaches or leaves 1/2,
   15 contact made or lost, 8 first and last point); *n_used (NULL allowed) = N. n: 0 or
   even, >= 8. When *n_points exceeds capacity the first capacity points are written and
   WA_CAPACITY_TOO_SMALL is returned (capacity 0 with NULL arrays asks for the count);
   on any other failure *n_points = *n_used = 0 and the arrays are not written. */
int wa_lj_trace(double alpha, double mu, int n, int n_profile, const double *profile,
                int capacity, double *P_star, double *gbar, double *a_star,
                double *b_star, int *stable_load, int *stable_gap, int *event,
                int *n_points, int *n_used, char *message, int message_capacity);

/* The gap and traction of the state at a_star (in [0, 1/2]; a* is half the measure of
   {h <= eps}, the contact): the traced state with a* nearest a_star among the
   load-stable points of the curve (all points when none is load-stable; the first in the
   order of the trace on a tie), so its own a* (state[0]) may differ from a_star by up to
   the trace's spacing. x_star[i] = i/N - 1/2, traction[i] = p/p* (positive =
   compressive) and gap[i] = h/Delta at the N grid nodes, i < N; state (NULL allowed)
   receives a*, b*, P*, gbar* of the state; *n_points = N (<= 16384, the grid cap). n: 0
   or even, >= 8. When N exceeds capacity the first capacity points are written, the
   state and *n_points too, and WA_CAPACITY_TOO_SMALL is returned (capacity 0 with NULL
   arrays asks for N, at the cost of the whole trace). WA_INVALID_ARGUMENT: alpha, mu, n,
   n_profile, a profile sample, a_star (NaN or outside [0, 1/2]), capacity < 0, n_points
   NULL or an array NULL while capacity > 0. On any other failure *n_points = 0, state is
   NaN and the arrays are not written. */
int wa_lj_profile(double alpha, double mu, int n, int n_profile, const double *profile,
                  double a_star, int capacity, double *x_star, double *traction,
                  double *gap, double *state, int *n_points, char *message,
                  int message_capacity);

/* 0.2 compatibility: removed in 0.4 */
/* The 0.2 names besides the functions above, each the function above with the 0.2
   arguments, bit for bit (doc/c-api.md, "Migrating from 0.2"): the _msg twins pass NULL
   for the optional output (gbar, row_status); the _gap variants require gbar (NULL:
   WA_INVALID_ARGUMENT) and have no message; wa_critical_sweep_status requires row_status
   when n_mu > 0; wa_adhesion_map_control is wa_adhesion_map with n_mu = 60 and no
   message. The 0.2 signatures of the base names (wa_equilibrium ... wa_adhesion_map
   without message) are gone: 0.3 changed them. */
int wa_equilibrium_msg(int model, double alpha, double mu, double a_star,
                       double *c_star, double *P_star, int *zone_case,
                       char *message, int message_capacity);
int wa_equilibrium_gap(int model, double alpha, double mu, double a_star,
                       double *c_star, double *P_star, int *zone_case, double *gbar);
int wa_equilibrium_gap_msg(int model, double alpha, double mu, double a_star,
                           double *c_star, double *P_star, int *zone_case, double *gbar,
                           char *message, int message_capacity);
int wa_roots_msg(int model, double alpha, double mu, double a_star, int capacity,
                 double *c_star, double *P_star, int *zone_case, int *n_roots,
                 char *message, int message_capacity);
int wa_roots_gap(int model, double alpha, double mu, double a_star, int capacity,
                 double *c_star, double *P_star, int *zone_case, double *gbar,
                 int *n_roots);
int wa_roots_gap_msg(int model, double alpha, double mu, double a_star, int capacity,
                     double *c_star, double *P_star, int *zone_case, double *gbar,
                     int *n_roots, char *message, int message_capacity);
int wa_trace_branch_msg(int model, double alpha, double mu, int capacity,
                        double *a_star, double *c_star, double *P_star, int *zone_case,
                        int *stable, int *event, int *n_points,
                        char *message, int message_capacity);
int wa_trace_branch_gap(int model, double alpha, double mu, int capacity,
                        double *a_star, double *c_star, double *P_star, int *zone_case,
                        int *stable, int *event, double *gbar, int *n_points);
int wa_trace_branch_gap_msg(int model, double alpha, double mu, int capacity,
                            double *a_star, double *c_star, double *P_star, int *zone_case,
                            int *stable, int *event, double *gbar, int *n_points,
                            char *message, int message_capacity);
int wa_profile_msg(int model, double alpha, double mu, double a_star, double c_star, int n,
                   const double *x_star, double *traction, double *gap, char *message,
                   int message_capacity);
int wa_critical_forces_msg(int model, double alpha, double mu, double *P_fc, double *P_pf,
                           char *message, int message_capacity);
int wa_load_path_msg(int model, double alpha, double mu, int capacity,
                     int *stage, int *event, double *a_star, double *c_star,
                     double *P_star, int *n_events, double *P_fc, double *P_pf,
                     char *message, int message_capacity);
int wa_critical_sweep_msg(int model, double alpha, int n_mu, const double *mu,
                          double *P_fc, double *P_pf, int *fc_mechanism, int *pf_mechanism,
                          char *message, int message_capacity);
int wa_critical_sweep_status(int model, double alpha, int n_mu, const double *mu,
                             double *P_fc, double *P_pf, int *fc_mechanism,
                             int *pf_mechanism, int *row_status, char *message,
                             int message_capacity);
int wa_adhesion_map_control(int model, int control, int n_alpha, const double *alpha,
                            double mu_lo, double mu_hi, int capacity, int *boundary_code,
                            double *alpha_out, double *mu_out, int *n_out);
int wa_gap_path_msg(int model, double alpha, double mu, int capacity,
                    int *stage, int *event, int *zone_case, double *a_star, double *c_star,
                    double *P_star, double *gbar, int *n_events,
                    double *W_star, double *W_fraction, double *g_touch,
                    char *message, int message_capacity);
int wa_gap_law_msg(int model, double alpha, double mu, int n, const double *gbar,
                   double *P_approach, double *P_retract, double *dPdg_approach,
                   double *dPdg_retract, char *message, int message_capacity);
int wa_gap_critical_msg(int model, double alpha, double mu, double *values, char *message,
                        int message_capacity);
/* end of the 0.2 compatibility block */

#ifdef __cplusplus
}
#endif
