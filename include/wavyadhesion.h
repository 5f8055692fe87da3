/*
 * wavyadhesion.h - C interface of the wavyadhesion library: adhesive contact of a
 * wavy (sinusoidal) elastic surface against a flat (Westergaard, JKR,
 * double-Westergaard and Maugis-Dugdale models), in dimensionless form.
 *
 * Copyright 2026, wavyadhesion developers. SPDX-License-Identifier: GPL-3.0-or-later
 *
 * Conventions (see doc/c-api.md):
 * - loads P* = mean traction / p*, p* = pi E* Delta / L (negative = tensile);
 *   widths a* = a/L and c* = c/L in [0, 1/2]; parameters alpha > 0 and mu >= 0;
 * - every function that takes pointers returns an int status (WA_OK = 0) and writes its
 *   results through the pointers; arrays are caller-allocated with an explicit
 *   capacity; nothing is allocated for the caller to free;
 * - NULL result pointers give WA_INVALID_ARGUMENT (never a crash);
 * - every function is thread safe (no global state).
 * Link with: -lwavyadhesion -lgfortran -lgsl -lgslcblas -lm
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

/* Status codes (equal to the wa_* constants of the Fortran module wa_status). */
#define WA_OK 0
#define WA_INVALID_ARGUMENT 1   /* an argument is NaN, infinite, out of range or NULL */
#define WA_NO_SOLUTION 2        /* the equations have no solution of the kind asked for */
#define WA_NOT_CONVERGED 3      /* an iteration did not reach its tolerance */
#define WA_CAPACITY_TOO_SMALL 4 /* an array is too small: only what fits was written */
#define WA_NUMERICAL_ERROR 5    /* a numerical building block (GSL, quadrature) failed */

/* Zone cases of a state (zone_inside, zone_whole_period, zone_full_contact). */
#define WA_ZONE_INSIDE 1        /* a* < c* < 1/2 */
#define WA_ZONE_WHOLE_PERIOD 2  /* a* < c* = 1/2 */
#define WA_ZONE_FULL_CONTACT 3  /* a* = c* = 1/2 */

/* Westergaard load P* = sin^2(pi a*); NaN when a_star is outside [0, 1/2] or NaN. */
double wa_westergaard_load(double a_star);

/* JKR load P* = sin^2(pi a*) - alpha sqrt(tan(pi a*)) (Johnson 1995); -Infinity at
   a* = 1/2 (alpha > 0); NaN when alpha < 0 or a_star is outside [0, 1/2]. */
double wa_jkr_load(double alpha, double a_star);

/* Principal equilibrium of `model` at a_star: c*, P* and zone case (DW, MD: the case-1
   state with the smallest c*, else the case-2 state; Westergaard, JKR: c* = a*, zone
   case 1, 3 at a* = 1/2). On failure *c_star = *P_star = NaN and *zone_case = 0. */
int wa_equilibrium(int model, double alpha, double mu, double a_star,
                   double *c_star, double *P_star, int *zone_case);

/* As wa_equilibrium; also copies the reason for a failure (naming the argument and its
   valid range; "" on success), truncated and NUL-terminated, into `message` when it is
   not NULL and message_capacity > 0. */
int wa_equilibrium_msg(int model, double alpha, double mu, double a_star,
                       double *c_star, double *P_star, int *zone_case,
                       char *message, int message_capacity);

/* Every equilibrium at a_star, case-1 states by increasing c*, then the case-2 state.
   *n_roots receives the total. When it exceeds `capacity` the first `capacity` states
   are written and WA_CAPACITY_TOO_SMALL is returned (capacity 0 with NULL arrays asks
   for the count). On any other failure *n_roots = 0. */
int wa_roots(int model, double alpha, double mu, double a_star, int capacity,
             double *c_star, double *P_star, int *zone_case, int *n_roots);

/* As wa_roots, with the message of wa_equilibrium_msg. */
int wa_roots_msg(int model, double alpha, double mu, double a_star, int capacity,
                 double *c_star, double *P_star, int *zone_case, int *n_roots,
                 char *message, int message_capacity);

/* Short fixed text of a status code: a static NUL-terminated string, never NULL
   ("unknown status" for codes the library does not return). Do not free it. */
const char *wa_status_message(int status);

#ifdef __cplusplus
}
#endif
