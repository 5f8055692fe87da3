/* C-interface test: `fpm test capi`. Calls every function of include/wavyadhesion.h (the
 * 0.3 functions, and every 0.2 compatibility name against them bit for bit) for every model, with valid and invalid arguments, NULL pointers and too small capacities;
 * branches, load paths and critical forces are compared with the numbers the command
 * line prints.
 * Prints one line per failed check and a closing "N passed, N failed"; exits non-zero
 * when anything failed. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "../../include/wavyadhesion.h"

static int n_pass = 0, n_fail = 0;

#define CHECK(cond, ...)                                                       \
   do {                                                                        \
      if (cond) {                                                              \
         n_pass++;                                                             \
      } else {                                                                 \
         n_fail++;                                                             \
         printf("FAIL %s:%d: ", __FILE__, __LINE__);                           \
         printf(__VA_ARGS__);                                                  \
         printf("\n");                                                         \
      }                                                                        \
   } while (0)

static const double pi = 3.14159265358979323846;
static const int models[4] = {WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW,
                              WA_MODEL_MD};

static int close_to(double got, double want, double tol) {
   return fabs(got - want) <= tol * (fabs(want) > 1.0 ? fabs(want) : 1.0);
}

static void test_closed_forms(void) {
   double a;
   for (a = 0.0; a <= 0.5; a += 0.0625) {
      double s = sin(pi * a);
      CHECK(close_to(wa_westergaard_load(a), s * s, 1e-14), "westergaard_load(%g)", a);
      if (a < 0.5)
         CHECK(close_to(wa_jkr_load(0.3, a), s * s - 0.3 * sqrt(tan(pi * a)), 1e-13),
               "jkr_load(0.3, %g)", a);
   }
   CHECK(isinf(wa_jkr_load(0.3, 0.5)) && wa_jkr_load(0.3, 0.5) < 0, "jkr at 1/2 is -inf");
   CHECK(isnan(wa_westergaard_load(0.7)), "westergaard_load outside domain is NaN");
   CHECK(isnan(wa_westergaard_load(-0.1)), "westergaard_load(-0.1) is NaN");
   CHECK(isnan(wa_jkr_load(-1.0, 0.2)), "jkr_load with alpha < 0 is NaN");
   CHECK(isnan(wa_jkr_load(0.3, NAN)), "jkr_load(NaN) is NaN");
}

static void test_status_messages(void) {
   static const char *want[] = {"ok", "invalid argument", "no solution",
                                "iteration did not converge", "output capacity too small",
                                "numerical error"};
   int codes[] = {WA_OK, WA_INVALID_ARGUMENT, WA_NO_SOLUTION, WA_NOT_CONVERGED,
                  WA_CAPACITY_TOO_SMALL, WA_NUMERICAL_ERROR};
   int i;
   for (i = 0; i < 6; i++) {
      const char *m = wa_status_message(codes[i]);
      CHECK(m != NULL && strcmp(m, want[i]) == 0, "status_message(%d) = '%s'", codes[i],
            m ? m : "(null)");
   }
   CHECK(wa_status_message(-1) != NULL && strcmp(wa_status_message(-1), "unknown status") == 0,
         "status_message(-1)");
   CHECK(wa_status_message(6) != NULL && strcmp(wa_status_message(6), "unknown status") == 0,
         "status_message(6)");
   CHECK(wa_status_message(1 << 30) != NULL, "status_message(huge) not NULL");
   CHECK(wa_status_message(0) == wa_status_message(0), "static storage");
}

/* Westergaard and JKR through wa_equilibrium: c* = a*, closed-form P*, zone 1 (3 at 1/2). */
static void test_equilibrium_closed_forms(void) {
   double c, p;
   int z, st;
   st = wa_equilibrium(WA_MODEL_WESTERGAARD, 0.3, 1.0, 0.25, &c, &p, &z, NULL, NULL, 0);
   CHECK(st == WA_OK && c == 0.25 && close_to(p, 0.5, 1e-15) && z == WA_ZONE_INSIDE,
         "westergaard at 1/4: st %d c %g P %g z %d", st, c, p, z);
   st = wa_equilibrium(WA_MODEL_WESTERGAARD, 0.3, 1.0, 0.5, &c, &p, &z, NULL, NULL, 0);
   CHECK(st == WA_OK && c == 0.5 && p == 1.0 && z == WA_ZONE_FULL_CONTACT,
         "westergaard at 1/2: st %d c %g P %g z %d", st, c, p, z);
   st = wa_equilibrium(WA_MODEL_JKR, 0.3, 1.0, 0.2, &c, &p, &z, NULL, NULL, 0);
   CHECK(st == WA_OK && c == 0.2 && p == wa_jkr_load(0.3, 0.2) && z == WA_ZONE_INSIDE,
         "jkr at 0.2: st %d c %g P %g z %d", st, c, p, z);
   st = wa_equilibrium(WA_MODEL_JKR, 0.3, 1.0, 0.5, &c, &p, &z, NULL, NULL, 0);
   CHECK(st == WA_OK && isinf(p) && p < 0 && z == WA_ZONE_FULL_CONTACT,
         "jkr at 1/2: st %d P %g z %d", st, p, z);
}

/* DW and MD: mu -> 0 is Westergaard, a* = 1/2 is full contact, a principal state is the
   first of the roots (to 1e-12: the two solves start from different brackets), results
   are finite and c* >= a*. */
static void test_equilibrium_cohesive(void) {
   int m, i;
   for (m = WA_MODEL_DW; m <= WA_MODEL_MD; m++) {
      double c, p;
      int z, st;
      st = wa_equilibrium(m, 0.3, 1e-12, 0.2, &c, &p, &z, NULL, NULL, 0);
      CHECK(st == WA_OK && close_to(p, wa_westergaard_load(0.2), 1e-9),
            "model %d, mu -> 0: st %d P %.17g", m, st, p);
      st = wa_equilibrium(m, 0.3, 0.0, 0.2, &c, &p, &z, NULL, NULL, 0);
      CHECK(st == WA_OK && close_to(p, wa_westergaard_load(0.2), 1e-14),
            "model %d, mu = 0: st %d P %.17g", m, st, p);
      st = wa_equilibrium(m, 0.3, 1.0, 0.5, &c, &p, &z, NULL, NULL, 0);
      CHECK(st == WA_OK && c == 0.5 && z == WA_ZONE_FULL_CONTACT,
            "model %d at 1/2: st %d c %g z %d", m, st, c, z);
      for (i = 1; i < 10; i++) {
         double a = 0.05 * i, cr[8], pr[8];
         int zr[8], n = -1;
         st = wa_equilibrium(m, 0.3, 1.0, a, &c, &p, &z, NULL, NULL, 0);
         CHECK(st == WA_OK && c >= a && c <= 0.5 && isfinite(p) &&
                  (z == WA_ZONE_INSIDE || z == WA_ZONE_WHOLE_PERIOD),
               "model %d at a* %g: st %d c %g P %g z %d", m, a, st, c, p, z);
         st = wa_roots(m, 0.3, 1.0, a, 8, cr, pr, zr, NULL, &n, NULL, 0);
         CHECK(st == WA_OK && n >= 1 && close_to(cr[0], c, 1e-12) && close_to(pr[0], p, 1e-12) &&
                  zr[0] == z,
               "model %d at a* %g: roots[0] is the principal state (st %d n %d)", m, a, st, n);
      }
   }
}

/* Invalid arguments give WA_INVALID_ARGUMENT and NaN outputs; NULL pointers too. */
static void test_equilibrium_invalid(void) {
   double c = 1, p = 1;
   int z = 7, i, m;
   const double bad_alpha[] = {0.0, -1.0, NAN, INFINITY};
   const double bad_mu[] = {-1e-3, NAN, INFINITY};
   const double bad_a[] = {-1e-3, 0.5000001, NAN, -INFINITY};
   for (m = 0; m < 4; m++) {
      for (i = 0; i < 4; i++) {
         int st = wa_equilibrium(models[m], bad_alpha[i], 1.0, 0.2, &c, &p, &z, NULL, NULL, 0);
         CHECK(st == WA_INVALID_ARGUMENT && isnan(c) && isnan(p) && z == 0,
               "model %d alpha %g: st %d", models[m], bad_alpha[i], st);
      }
      for (i = 0; i < 3; i++)
         CHECK(wa_equilibrium(models[m], 0.3, bad_mu[i], 0.2, &c, &p, &z, NULL, NULL, 0) ==
                  WA_INVALID_ARGUMENT,
               "model %d mu %g", models[m], bad_mu[i]);
      for (i = 0; i < 4; i++)
         CHECK(wa_equilibrium(models[m], 0.3, 1.0, bad_a[i], &c, &p, &z, NULL, NULL, 0) ==
                  WA_INVALID_ARGUMENT,
               "model %d a* %g", models[m], bad_a[i]);
      CHECK(wa_equilibrium(models[m], 0.3, 1.0, 0.2, NULL, &p, &z, NULL, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL c_star");
      CHECK(wa_equilibrium(models[m], 0.3, 1.0, 0.2, &c, NULL, &z, NULL, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL P_star");
      CHECK(wa_equilibrium(models[m], 0.3, 1.0, 0.2, &c, &p, NULL, NULL, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL zone_case");
   }
   CHECK(wa_equilibrium(4, 0.3, 1.0, 0.2, &c, &p, &z, NULL, NULL, 0) == WA_INVALID_ARGUMENT, "model 4");
   CHECK(wa_equilibrium(-1, 0.3, 1.0, 0.2, &c, &p, &z, NULL, NULL, 0) == WA_INVALID_ARGUMENT, "model -1");
}

static void test_messages(void) {
   double c, p;
   int z, st;
   char msg[128], tiny[6];
   memset(msg, 'x', sizeof msg);
   st = wa_equilibrium_msg(WA_MODEL_DW, 0.3, 1.0, 0.7, &c, &p, &z, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "a_star") && strstr(msg, "[0, 1/2]"),
         "message names a_star and its range: '%s'", msg);
   st = wa_equilibrium_msg(WA_MODEL_MD, -2.0, 1.0, 0.2, &c, &p, &z, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "alpha"), "alpha message: '%s'", msg);
   st = wa_equilibrium_msg(9, 0.3, 1.0, 0.2, &c, &p, &z, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "model"), "model message: '%s'", msg);
   memset(tiny, 'x', sizeof tiny);
   st = wa_equilibrium_msg(WA_MODEL_DW, 0.3, 1.0, 0.7, &c, &p, &z, tiny, sizeof tiny);
   CHECK(st == WA_INVALID_ARGUMENT && strlen(tiny) == 5, "truncated message: '%s'", tiny);
   st = wa_equilibrium_msg(WA_MODEL_DW, 0.3, 1.0, 0.2, &c, &p, &z, msg, sizeof msg);
   CHECK(st == WA_OK && msg[0] == '\0', "empty message on success");
   st = wa_equilibrium_msg(WA_MODEL_DW, 0.3, 1.0, 0.7, &c, &p, &z, NULL, 0);
   CHECK(st == WA_INVALID_ARGUMENT, "NULL message buffer is accepted");
   st = wa_roots_msg(WA_MODEL_JKR, 0.3, 1.0, 0.2, -1, NULL, NULL, NULL, &z, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "capacity"), "capacity message: '%s'", msg);
   st = wa_roots_msg(WA_MODEL_JKR, 0.3, 1.0, 0.2, 0, NULL, NULL, NULL, &z, msg, sizeof msg);
   CHECK(st == WA_CAPACITY_TOO_SMALL && z == 1 && strstr(msg, "capacity"),
         "roots capacity message: '%s'", msg);
}

/* Closed-form models have one root; capacity 0 with NULL arrays asks for the count. */
static void test_roots_closed_forms(void) {
   int m;
   for (m = WA_MODEL_WESTERGAARD; m <= WA_MODEL_JKR; m++) {
      double c[2] = {-1, -1}, p[2] = {-1, -1};
      int z[2] = {-1, -1}, n = -1, st;
      st = wa_roots(m, 0.3, 1.0, 0.2, 2, c, p, z, NULL, &n, NULL, 0);
      CHECK(st == WA_OK && n == 1 && c[0] == 0.2 && z[0] == WA_ZONE_INSIDE && c[1] == -1,
            "model %d roots: st %d n %d", m, st, n);
      CHECK(p[0] == (m == WA_MODEL_JKR ? wa_jkr_load(0.3, 0.2) : wa_westergaard_load(0.2)),
            "model %d root load", m);
      st = wa_roots(m, 0.3, 1.0, 0.2, 0, NULL, NULL, NULL, NULL, &n, NULL, 0);
      CHECK(st == WA_CAPACITY_TOO_SMALL && n == 1, "model %d count query: st %d n %d", m, st,
            n);
   }
}

/* Invalid arguments and NULL pointers for wa_roots, for every model. */
static void test_roots_invalid(void) {
   double c[4], p[4];
   int z[4], n, m;
   for (m = 0; m < 4; m++) {
      int md = models[m];
      n = 5;
      CHECK(wa_roots(md, 0.3, 1.0, 0.9, 4, c, p, z, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT && n == 0,
            "model %d a* 0.9", md);
      CHECK(wa_roots(md, NAN, 1.0, 0.2, 4, c, p, z, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT && n == 0,
            "model %d alpha NaN", md);
      CHECK(wa_roots(md, 0.3, -1.0, 0.2, 4, c, p, z, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT, "mu < 0");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, -3, c, p, z, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "capacity < 0");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, 4, c, p, z, NULL, NULL, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL n_roots");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, 4, NULL, p, z, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL c_star");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, 4, c, NULL, z, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL P_star");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, 4, c, p, NULL, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL zone_case");
   }
   CHECK(wa_roots(17, 0.3, 1.0, 0.2, 4, c, p, z, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT && n == 0,
         "model 17");
}

/* DW and MD on a grid: every root is finite with a* <= c* <= 1/2. */
static void test_roots_grid(void) {
   static const double alphas[] = {0.1, 0.3, 1.0};
   static const double mus[] = {0.3, 1.0, 10.0};
   int m, ia, im, i, k;
   for (m = WA_MODEL_DW; m <= WA_MODEL_MD; m++)
      for (ia = 0; ia < 3; ia++)
         for (im = 0; im < 3; im++)
            for (i = 1; i < 50; i++) {
               double a = 0.01 * i, c[8], p[8];
               int z[8], n = 0;
               int st = wa_roots(m, alphas[ia], mus[im], a, 8, c, p, z, NULL, &n, NULL, 0);
               CHECK(st == WA_OK && n >= 1, "model %d roots at (%g, %g, %g): st %d n %d", m,
                     alphas[ia], mus[im], a, st, n);
               for (k = 0; k < n && k < 8; k++)
                  CHECK(isfinite(c[k]) && isfinite(p[k]) && c[k] >= a && c[k] <= 0.5,
                        "model %d root %d at (%g, %g, %g): c* %g P* %g", m, k, alphas[ia],
                        mus[im], a, c[k], p[k]);
            }
}

/* MD at (alpha, mu, a*) = (0.3, 1, 0.3) has three states (two case 1, one case 2; see
   test/data/md.txt): capacities 0, 1 and 2 must return WA_CAPACITY_TOO_SMALL with the
   full count, write the first states only, and nothing beyond. */
static void test_roots_capacity(void) {
   double c[3], p[3];
   int z[3], n = 0, cap, k;
   int st = wa_roots(WA_MODEL_MD, 0.3, 1.0, 0.3, 3, c, p, z, NULL, &n, NULL, 0);
   CHECK(st == WA_OK && n == 3 && z[0] == 1 && z[1] == 1 && z[2] == 2 && c[0] < c[1],
         "md at (0.3, 1, 0.3): st %d n %d (want 3 states: 1, 1, 2)", st, n);
   if (st != WA_OK || n < 2) return;
   for (cap = 0; cap < n; cap++) {
      double c1[4] = {-7, -7, -7, -7}, p1[4] = {-7, -7, -7, -7};
      int z1[4] = {-7, -7, -7, -7}, n1 = 0;
      st = wa_roots(WA_MODEL_MD, 0.3, 1.0, 0.3, cap, c1, p1, z1, NULL, &n1, NULL, 0);
      CHECK(st == WA_CAPACITY_TOO_SMALL && n1 == n, "capacity %d: st %d n %d", cap, st, n1);
      for (k = 0; k < cap; k++)
         CHECK(c1[k] == c[k] && p1[k] == p[k] && z1[k] == z[k], "capacity %d: state %d", cap,
               k);
      for (k = cap; k < 4; k++)
         CHECK(c1[k] == -7 && p1[k] == -7 && z1[k] == -7,
               "capacity %d: element %d written beyond capacity", cap, k);
   }
   {
      char msg[128];
      st = wa_roots_msg(WA_MODEL_MD, 0.3, 1.0, 0.3, 1, c, p, z, &n, msg, sizeof msg);
      CHECK(st == WA_CAPACITY_TOO_SMALL && msg[0] != '\0', "message: '%s'", msg);
   }
   for (k = WA_MODEL_DW; k <= WA_MODEL_MD; k++) {   /* capacity 0: count only */
      double c0[1] = {-7};
      int n0 = 0;
      st = wa_roots(k, 0.3, 1.0, 0.2, 0, c0, NULL, NULL, NULL, &n0, NULL, 0);
      CHECK(st == WA_CAPACITY_TOO_SMALL && n0 >= 1 && c0[0] == -7,
            "model %d capacity 0: st %d n %d", k, st, n0);
   }
}

/* Thread safety: 4 threads computing the same grid at once get the serial results. */
#define GRID 400
typedef struct {
   int model;
   double c[GRID], p[GRID];
   int z[GRID], st[GRID];
} grid_job;

static void *run_grid(void *arg) {
   grid_job *job = (grid_job *)arg;
   int i;
   for (i = 0; i < GRID; i++)
      job->st[i] = wa_equilibrium(job->model, 0.1 + 0.002 * i, 0.5 + 0.01 * i,
                                  0.5 * (i + 1) / (GRID + 1), &job->c[i], &job->p[i],
                                  &job->z[i], NULL, NULL, 0);
   return NULL;
}

static void test_threads(void) {
   static grid_job serial, threaded[4];
   pthread_t tid[4];
   int m, t, i;
   for (m = 0; m < 4; m++) {
      serial.model = models[m];
      run_grid(&serial);
      for (t = 0; t < 4; t++) {
         threaded[t].model = models[m];
         CHECK(pthread_create(&tid[t], NULL, run_grid, &threaded[t]) == 0, "pthread_create");
      }
      for (t = 0; t < 4; t++) pthread_join(tid[t], NULL);
      for (t = 0; t < 4; t++) {
         int same = 1;
         for (i = 0; i < GRID; i++)
            same = same && threaded[t].st[i] == serial.st[i] &&
                   memcmp(&threaded[t].c[i], &serial.c[i], sizeof(double)) == 0 &&
                   memcmp(&threaded[t].p[i], &serial.p[i], sizeof(double)) == 0 &&
                   threaded[t].z[i] == serial.z[i];
         CHECK(same, "model %d thread %d: results differ from the serial ones", models[m], t);
      }
   }
}

/* ------------------------------------------------------------ continuation */

#define BRANCH_CAP 4000
typedef struct {
   double a[BRANCH_CAP], c[BRANCH_CAP], p[BRANCH_CAP];
   int z[BRANCH_CAP], s[BRANCH_CAP], e[BRANCH_CAP], n, st;
} branch_buf;

static int trace(int model, double alpha, double mu, branch_buf *b) {
   b->n = -1;
   b->st = wa_trace_branch(model, alpha, mu, BRANCH_CAP, b->a, b->c, b->p, b->z, b->s, b->e, NULL,
                           &b->n, NULL, 0);
   return b->st;
}

static int count_events(const branch_buf *b, int code) {
   int i, k = 0;
   for (i = 0; i < b->n; i++) k += b->e[i] == code;
   return k;
}

/* Every model: a well-formed branch from a* -> 0 to a* = 1/2 whose points are equilibria
   (each P* is among the wa_roots states at that a*, to 1e-9; zone-case switches are
   skipped: exactly at the switch the case-1 and case-2 states coincide, and wa_roots may
   return only the case-1 state there). */
static void test_branch_every_model(void) {
   static branch_buf b;
   int m, i, k;
   for (m = 0; m < 4; m++) {
      int st = trace(models[m], 0.3, 1.0, &b), ok = 1, on_curve = 1;
      CHECK(st == WA_OK && b.n > 100 && b.n <= BRANCH_CAP, "model %d branch: st %d n %d",
            models[m], st, b.n);
      if (st != WA_OK) continue;
      CHECK(b.e[0] == WA_EVENT_BRANCH_END && b.e[b.n - 1] == WA_EVENT_BRANCH_END &&
               b.a[0] < 1e-5 && b.a[b.n - 1] > 0.5 - 1e-8,
            "model %d: branch ends: a* %g .. %g, events %d %d", models[m], b.a[0],
            b.a[b.n - 1], b.e[0], b.e[b.n - 1]);
      for (i = 0; i < b.n; i++)
         ok = ok && (b.a[i] > 0 || (b.a[i] == 0 && b.z[i] == WA_ZONE_NO_CONTACT)) &&
              b.a[i] <= 0.5 && b.c[i] >= b.a[i] && b.c[i] <= 0.5 &&
              isfinite(b.p[i]) && b.z[i] >= 0 && b.z[i] <= 3 &&
              (b.s[i] == 0 || b.s[i] == 1) && b.e[i] >= WA_EVENT_NONE &&
              b.e[i] <= WA_EVENT_A_TURN && (b.e[i] != WA_EVENT_FOLD || b.s[i] == 0);
      CHECK(ok, "model %d: every point well formed", models[m]);
      if (models[m] == WA_MODEL_JKR)
         CHECK(count_events(&b, WA_EVENT_FOLD) == 2, "jkr alpha 0.3: two folds (got %d)",
               count_events(&b, WA_EVENT_FOLD));
      if (models[m] == WA_MODEL_WESTERGAARD)
         CHECK(count_events(&b, WA_EVENT_FOLD) == 0 && b.z[b.n - 1] == WA_ZONE_FULL_CONTACT,
               "westergaard: no fold, ends in full contact");
      for (i = 1; i < b.n - 1; i++) {
         double cr[8], pr[8];
         int zr[8], nr = 0, found = 0;
         if (b.e[i] == WA_EVENT_SWITCH) continue;
         /* where a* turns back two roots merge: the root finder cannot separate them */
         if ((b.a[i] - b.a[i - 1]) * (b.a[i + 1] - b.a[i]) <= 0) continue;
         if (wa_roots(models[m], 0.3, 1.0, b.a[i], 8, cr, pr, zr, NULL, &nr, NULL, 0) != WA_OK) {
            on_curve = 0;
            break;
         }
         for (k = 0; k < nr && k < 8; k++) found = found || close_to(pr[k], b.p[i], 1e-9);
         if (!found) {
            on_curve = 0;
            printf("  model %d point %d: a* %.17g P* %.17g not among %d roots\n", models[m],
                   i, b.a[i], b.p[i], nr);
            break;
         }
      }
      CHECK(on_curve, "model %d: branch points are equilibria", models[m]);
   }
}

/* DW at alpha = 0.3, mu = 5 (paper Fig. 6): two folds and one zone-case switch, where
   `wavyadhesion branch --model dw --alpha 0.3 --mu 5` puts them. */
static void test_branch_dw_values(void) {
   static branch_buf b;
   static const double fold_a[2] = {5.3308276396925647e-02, 3.7313491247966202e-01};
   static const double fold_p[2] = {-9.5883008684625154e-02, 3.8750724174362783e-01};
   int i, k = 0, st = trace(WA_MODEL_DW, 0.3, 5.0, &b);
   CHECK(st == WA_OK && count_events(&b, WA_EVENT_FOLD) == 2 &&
            count_events(&b, WA_EVENT_SWITCH) == 1,
         "dw (0.3, 5): st %d, %d folds, %d switches (want 2, 1)", st,
         count_events(&b, WA_EVENT_FOLD), count_events(&b, WA_EVENT_SWITCH));
   for (i = 0; i < b.n; i++) {
      if (b.e[i] == WA_EVENT_FOLD && k < 2) {
         CHECK(close_to(b.a[i], fold_a[k], 1e-10) && close_to(b.p[i], fold_p[k], 1e-12),  /* folds to 1e-10 (accuracy target) */
               "dw fold %d: a* %.17g P* %.17g", k, b.a[i], b.p[i]);
         k++;
      }
      if (b.e[i] == WA_EVENT_SWITCH)
         CHECK(close_to(b.a[i], 4.6606802365917238e-01, 1e-12) &&
                  close_to(b.p[i], -1.1995262953240982e-01, 1e-12) && b.c[i] == 0.5 &&
                  b.z[i] == WA_ZONE_WHOLE_PERIOD,
               "dw switch: a* %.17g P* %.17g zone %d", b.a[i], b.p[i], b.z[i]);
   }
   CHECK(b.z[b.n - 1] == WA_ZONE_FULL_CONTACT && b.a[b.n - 1] == 0.5, "dw ends at 1/2");
}

/* Capacity: 0 with NULL arrays counts; a short buffer gets the first points, nothing
   beyond, the full count and WA_CAPACITY_TOO_SMALL. */
static void test_branch_capacity(void) {
   static branch_buf full;
   double a[12], c[12], p[12];
   int z[12], s[12], e[12], m, n, i, st;
   char msg[256];
   for (m = 0; m < 4; m++) {
      if (trace(models[m], 0.3, 5.0, &full) != WA_OK) {
         CHECK(0, "model %d: trace failed", models[m]);
         continue;
      }
      n = -1;
      st = wa_trace_branch(models[m], 0.3, 5.0, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL, &n, NULL, 0);
      CHECK(st == WA_CAPACITY_TOO_SMALL && n == full.n, "model %d count query: st %d n %d/%d",
            models[m], st, n, full.n);
      for (i = 0; i < 12; i++) {
         a[i] = c[i] = p[i] = -7;
         z[i] = s[i] = e[i] = -7;
      }
      st = wa_trace_branch(models[m], 0.3, 5.0, 10, a, c, p, z, s, e, NULL, &n, NULL, 0);
      CHECK(st == WA_CAPACITY_TOO_SMALL && n == full.n, "model %d capacity 10: st %d n %d",
            models[m], st, n);
      for (i = 0; i < 10; i++)
         CHECK(a[i] == full.a[i] && c[i] == full.c[i] && p[i] == full.p[i] &&
                  z[i] == full.z[i] && s[i] == full.s[i] && e[i] == full.e[i],
               "model %d capacity 10: point %d", models[m], i);
      for (i = 10; i < 12; i++)
         CHECK(a[i] == -7 && c[i] == -7 && p[i] == -7 && z[i] == -7 && s[i] == -7 &&
                  e[i] == -7,
               "model %d: element %d written beyond capacity", models[m], i);
   }
   st = wa_trace_branch_msg(WA_MODEL_DW, 0.3, 5.0, 10, a, c, p, z, s, e, &n, msg, sizeof msg);
   CHECK(st == WA_CAPACITY_TOO_SMALL && strstr(msg, "capacity = 10"), "message: '%s'", msg);
}

/* NULL pointers, negative capacity, invalid model, alpha, mu: WA_INVALID_ARGUMENT,
   *n_points = 0, nothing written. */
static void test_branch_invalid(void) {
   double a[4] = {-7, -7, -7, -7}, c[4], p[4];
   int z[4], s[4], e[4], n, m, i;
   char msg[256];
   const double bad_alpha[] = {0.0, -1.0, NAN, INFINITY};
   const double bad_mu[] = {-1e-3, NAN, INFINITY};
   for (m = 0; m < 4; m++) {
      int md = models[m];
      CHECK(wa_trace_branch(md, 0.3, 1.0, 4, a, c, p, z, s, e, NULL, NULL, NULL, 0) == WA_INVALID_ARGUMENT,
            "model %d NULL n_points", md);
      CHECK(wa_trace_branch(md, 0.3, 1.0, -1, a, c, p, z, s, e, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "model %d capacity -1", md);
      CHECK(wa_trace_branch(md, 0.3, 1.0, 4, NULL, c, p, z, s, e, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL a_star");
      CHECK(wa_trace_branch(md, 0.3, 1.0, 4, a, NULL, p, z, s, e, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL c_star");
      CHECK(wa_trace_branch(md, 0.3, 1.0, 4, a, c, NULL, z, s, e, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL P_star");
      CHECK(wa_trace_branch(md, 0.3, 1.0, 4, a, c, p, NULL, s, e, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL zone_case");
      CHECK(wa_trace_branch(md, 0.3, 1.0, 4, a, c, p, z, NULL, e, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL stable");
      CHECK(wa_trace_branch(md, 0.3, 1.0, 4, a, c, p, z, s, NULL, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL event");
      for (i = 0; i < 4; i++) {
         n = 5;
         CHECK(wa_trace_branch(md, bad_alpha[i], 1.0, 4, a, c, p, z, s, e, NULL, &n, NULL, 0) ==
                  WA_INVALID_ARGUMENT && n == 0,
               "model %d alpha %g", md, bad_alpha[i]);
      }
      for (i = 0; i < 3; i++) {
         n = 5;
         CHECK(wa_trace_branch(md, 0.3, bad_mu[i], 4, a, c, p, z, s, e, NULL, &n, NULL, 0) ==
                  WA_INVALID_ARGUMENT && n == 0,
               "model %d mu %g", md, bad_mu[i]);
      }
   }
   n = 5;
   CHECK(wa_trace_branch(4, 0.3, 1.0, 4, a, c, p, z, s, e, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT &&
            n == 0,
         "model 4");
   CHECK(wa_trace_branch(-1, 0.3, 1.0, 4, a, c, p, z, s, e, NULL, &n, NULL, 0) == WA_INVALID_ARGUMENT,
         "model -1");
   CHECK(a[0] == -7, "nothing written on invalid arguments");
   CHECK(wa_trace_branch_msg(WA_MODEL_DW, -0.3, 1.0, 4, a, c, p, z, s, e, &n, msg,
                             sizeof msg) == WA_INVALID_ARGUMENT &&
            strstr(msg, "alpha") && strstr(msg, "[1e-12, 1e12]"),
         "alpha message: '%s'", msg);
   CHECK(wa_trace_branch_msg(WA_MODEL_DW, 0.3, 1.0, 4, NULL, c, p, z, s, e, &n, msg,
                             sizeof msg) == WA_INVALID_ARGUMENT &&
            strstr(msg, "NULL"),
         "NULL message: '%s'", msg);
   CHECK(wa_trace_branch_msg(7, 0.3, 1.0, 4, a, c, p, z, s, e, &n, msg, sizeof msg) ==
            WA_INVALID_ARGUMENT && strstr(msg, "model"),
         "model message: '%s'", msg);
   CHECK(wa_trace_branch_msg(WA_MODEL_DW, 0.3, 1.0, 4000, NULL, NULL, NULL, NULL, NULL, NULL,
                             &n, msg, sizeof msg) == WA_INVALID_ARGUMENT,
         "NULL arrays with capacity > 0");
}

/* P_fc*, P_pf* as `wavyadhesion critical --model M --alpha A --mu U` prints them (the
   CLI writes 17 significant digits, so these are the same doubles to ~1 ulp). */
static void test_critical_values(void) {
   static const struct {
      int model;
      double alpha, mu, p_fc, p_pf;
   } cases[] = {
      {WA_MODEL_DW, 0.3, 0.1, 9.7782736093678035e-01, -2.2172639063219639e-02},
      {WA_MODEL_DW, 0.3, 1.0, 7.7827360936780365e-01, -8.8714284799719476e-02},
      {WA_MODEL_DW, 0.3, 5.0, 3.8750724174362811e-01, -1.1995262953240982e-01},
      {WA_MODEL_DW, 0.6, 0.1, 9.6480312942613400e-01, -3.5196870573866043e-02},
      {WA_MODEL_DW, 0.6, 1.0, 6.4803129426133954e-01, -2.3352051827366549e-01},
      {WA_MODEL_DW, 0.6, 5.0, 0.0, -7.8778223218930721e-01},
      {WA_MODEL_DW, 1.0, 1.0, 5.0523016069339088e-01, -4.9476983930660912e-01},
      {WA_MODEL_MD, 0.3, 1.0, 5.5654721873560731e-01, -9.0525660009991279e-02},
      {WA_MODEL_MD, 0.3, 5.0, 3.8764647725517604e-01, -1.3466548525864468e+00},
   };
   int i, m;
   for (i = 0; i < (int)(sizeof cases / sizeof cases[0]); i++) {
      double fc = 1, pf = 1;
      int st = wa_critical_forces(cases[i].model, cases[i].alpha, cases[i].mu, &fc, &pf, NULL, 0);
      CHECK(st == WA_OK && close_to(fc, cases[i].p_fc, 1e-14) &&
               close_to(pf, cases[i].p_pf, 1e-14),
            "critical model %d (%g, %g): st %d P_fc %.17g P_pf %.17g", cases[i].model,
            cases[i].alpha, cases[i].mu, st, fc, pf);
   }
   for (i = 0; i < 3; i++) {        /* JKR: P_fc independent of mu, P_pf = -inf */
      double fc, pf;
      int st = wa_critical_forces(WA_MODEL_JKR, 0.3, 0.5 * i, &fc, &pf, NULL, 0);
      CHECK(st == WA_OK && close_to(fc, 3.8772776072055104e-01, 1e-14) && isinf(pf) &&
               pf < 0,
            "jkr critical: st %d P_fc %.17g P_pf %g", st, fc, pf);
   }
   for (m = 0; m < 4; m++) {        /* the same numbers through every route */
      double fc, pf, fc2, pf2, fcs[2], pfs[2], mus[2] = {1.0, 5.0};
      double a[64], c[64], p[64];
      int stage[64], ev[64], n = 0, fm[2], pm[2], k, st1, st2, st3;
      st1 = wa_critical_forces(models[m], 0.3, 5.0, &fc, &pf, NULL, 0);
      st2 = wa_load_path(models[m], 0.3, 5.0, 64, stage, ev, a, c, p, &n, &fc2, &pf2, NULL, 0);
      st3 = wa_critical_sweep(models[m], 0.3, 2, mus, fcs, pfs, fm, pm, NULL, NULL, 0);
      CHECK(st1 == WA_OK && st2 == WA_OK && st3 == WA_OK &&
               memcmp(&fc, &fc2, sizeof fc) == 0 && memcmp(&pf, &pf2, sizeof pf) == 0 &&
               memcmp(&fc, &fcs[1], sizeof fc) == 0 && memcmp(&pf, &pfs[1], sizeof pf) == 0,
            "model %d: critical_forces, load_path and critical_sweep agree", models[m]);
      for (k = 0; k < n; k++) {
         if (ev[k] == WA_EVENT_FULL_CONTACT_REACHED)
            CHECK(p[k] == fc && stage[k] == WA_STAGE_LOADING, "model %d: P at full contact",
                  models[m]);
         if (ev[k] == WA_EVENT_PULL_OFF)
            CHECK(memcmp(&p[k], &pf, sizeof pf) == 0 && stage[k] == WA_STAGE_UNLOADING,
                  "model %d: P at pull-off", models[m]);
      }
   }
}

static void test_critical_invalid(void) {
   double fc = 1, pf = 1;
   int m;
   char msg[256];
   for (m = 0; m < 4; m++) {
      CHECK(wa_critical_forces(models[m], 0.3, 1.0, NULL, &pf, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL P_fc");
      CHECK(wa_critical_forces(models[m], 0.3, 1.0, &fc, NULL, NULL, 0) == WA_INVALID_ARGUMENT,
            "NULL P_pf");
      fc = pf = 1;
      CHECK(wa_critical_forces(models[m], 0.0, 1.0, &fc, &pf, NULL, 0) == WA_INVALID_ARGUMENT &&
               isnan(fc) && isnan(pf),
            "model %d alpha 0: NaN outputs", models[m]);
      CHECK(wa_critical_forces(models[m], NAN, 1.0, &fc, &pf, NULL, 0) == WA_INVALID_ARGUMENT,
            "alpha NaN");
      CHECK(wa_critical_forces(models[m], 0.3, -1.0, &fc, &pf, NULL, 0) == WA_INVALID_ARGUMENT,
            "mu < 0");
      CHECK(wa_critical_forces(models[m], 0.3, INFINITY, &fc, &pf, NULL, 0) == WA_INVALID_ARGUMENT,
            "mu inf");
   }
   CHECK(wa_critical_forces(5, 0.3, 1.0, &fc, &pf, NULL, 0) == WA_INVALID_ARGUMENT && isnan(fc),
         "model 5");
   CHECK(wa_critical_forces_msg(WA_MODEL_MD, 0.3, -2.0, &fc, &pf, msg, sizeof msg) ==
            WA_INVALID_ARGUMENT && strstr(msg, "mu") && strstr(msg, "0 or [1e-100, 1e100]"),
         "mu message: '%s'", msg);
   CHECK(wa_critical_forces_msg(WA_MODEL_MD, 0.3, 1.0, &fc, &pf, msg, sizeof msg) == WA_OK &&
            msg[0] == '\0',
         "empty message on success");
}

/* Load paths: the event sequence of `wavyadhesion path --model dw --alpha 0.3 --mu 5`,
   capacity handling, invalid arguments. */
static void test_load_path(void) {
   static const int want_stage[7] = {1, 1, 1, 1, 2, 2, 2};
   static const int want_event[7] = {3, 4, 3, 5, 6, 3, 7};
   double a[8], c[8], p[8], fc, pf;
   int stage[8], ev[8], n = -1, k, st, m, same = 1;
   char msg[256];
   st = wa_load_path(WA_MODEL_DW, 0.3, 5.0, 8, stage, ev, a, c, p, &n, &fc, &pf, NULL, 0);
   CHECK(st == WA_OK && n == 7, "dw path (0.3, 5): st %d n %d (want 7)", st, n);
   for (k = 0; k < 7 && n == 7; k++)
      same = same && stage[k] == want_stage[k] && ev[k] == want_event[k];
   CHECK(same, "dw path (0.3, 5): stages and events as the CLI prints them");
   CHECK(n == 7 && close_to(a[1], 1.4954454098314016e-01, 1e-12) && p[1] == 0.0 &&
            close_to(p[2], 3.8750724174362783e-01, 1e-14) &&
            close_to(p[4], -1.0863195316098184e-01, 1e-12),
         "dw path values: a %.17g P %.17g %.17g", a[1], p[2], p[4]);
   for (k = 0; k < 8; k++) {
      a[k] = -7;
      ev[k] = -7;
   }
   st = wa_load_path(WA_MODEL_DW, 0.3, 5.0, 3, stage, ev, a, c, p, &n, &fc, &pf, NULL, 0);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n == 7 && ev[2] == 3 && ev[3] == -7 && a[3] == -7 &&
            close_to(fc, 3.8750724174362783e-01, 1e-14),
         "path capacity 3: st %d n %d", st, n);
   st = wa_load_path(WA_MODEL_JKR, 0.3, 1.0, 0, NULL, NULL, NULL, NULL, NULL, &n, &fc, &pf, NULL, 0);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n == 5 && isinf(pf) && pf < 0,
         "jkr path count: st %d n %d", st, n);
   for (m = 0; m < 4; m++) {
      int md = models[m];
      CHECK(wa_load_path(md, 0.3, 1.0, 8, stage, ev, a, c, p, NULL, &fc, &pf, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "NULL n_events");
      CHECK(wa_load_path(md, 0.3, 1.0, 8, stage, ev, a, c, p, &n, NULL, &pf, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "NULL P_fc");
      CHECK(wa_load_path(md, 0.3, 1.0, 8, stage, ev, a, c, p, &n, &fc, NULL, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "NULL P_pf");
      CHECK(wa_load_path(md, 0.3, 1.0, 8, NULL, ev, a, c, p, &n, &fc, &pf, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "NULL stage");
      CHECK(wa_load_path(md, 0.3, 1.0, 8, stage, ev, a, c, NULL, &n, &fc, &pf, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "NULL P_star");
      CHECK(wa_load_path(md, 0.3, 1.0, -2, stage, ev, a, c, p, &n, &fc, &pf, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "capacity -2");
      n = 3;
      CHECK(wa_load_path(md, -0.3, 1.0, 8, stage, ev, a, c, p, &n, &fc, &pf, NULL, 0) ==
               WA_INVALID_ARGUMENT && n == 0 && isnan(fc) && isnan(pf),
            "model %d alpha < 0", md);
      CHECK(wa_load_path(md, 0.3, NAN, 8, stage, ev, a, c, p, &n, &fc, &pf, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "mu NaN");
   }
   CHECK(wa_load_path(9, 0.3, 1.0, 8, stage, ev, a, c, p, &n, &fc, &pf, NULL, 0) ==
            WA_INVALID_ARGUMENT,
         "model 9");
   st = wa_load_path_msg(WA_MODEL_DW, 0.3, 5.0, 3, stage, ev, a, c, p, &n, &fc, &pf, msg,
                         sizeof msg);
   CHECK(st == WA_CAPACITY_TOO_SMALL && strstr(msg, "7 events"), "path message: '%s'", msg);
}

/* Sweeps: the mechanisms the CLI's mechanism notes locate (DW, alpha 0.3: P_pf gradual ->
   jump case 1 at mu 0.580, P_fc gradual -> jump case 1 at 2.77, P_pf jump case 1 -> case 2
   at 4.89); an invalid mu anywhere fails the whole sweep before any work. */
static void test_critical_sweep(void) {
   double mu[3] = {0.1, 1.0, 5.0}, fc[3], pf[3];
   int fm[3], pm[3], st, i;
   char msg[256];
   st = wa_critical_sweep(WA_MODEL_DW, 0.3, 3, mu, fc, pf, fm, pm, NULL, NULL, 0);
   CHECK(st == WA_OK && fm[0] == WA_MECHANISM_GRADUAL && pm[0] == WA_MECHANISM_GRADUAL &&
            fm[1] == WA_MECHANISM_GRADUAL && pm[1] == WA_MECHANISM_JUMP_CASE1 &&
            fm[2] == WA_MECHANISM_JUMP_CASE1 && pm[2] == WA_MECHANISM_JUMP_CASE2,
         "dw sweep mechanisms: st %d fc %d %d %d pf %d %d %d", st, fm[0], fm[1], fm[2], pm[0],
         pm[1], pm[2]);
   for (i = 0; i < 3; i++) {
      double f1, p1;
      wa_critical_forces(WA_MODEL_DW, 0.3, mu[i], &f1, &p1, NULL, 0);
      CHECK(fc[i] == f1 && pf[i] == p1, "sweep point %d equals wa_critical_forces", i);
   }
   st = wa_critical_sweep(WA_MODEL_DW, 0.6, 1, mu + 2, fc, pf, fm, pm, NULL, NULL, 0);
   CHECK(st == WA_OK && fm[0] == WA_MECHANISM_SNAP && fc[0] == 0.0,
         "dw (0.6, 5): full contact by a snap at P* = 0 (st %d mech %d)", st, fm[0]);
   mu[1] = -1.0;
   st = wa_critical_sweep_msg(WA_MODEL_DW, 0.3, 3, mu, fc, pf, fm, pm, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && isnan(fc[0]) && isnan(pf[2]) && fm[0] == -1 &&
            pm[2] == -1 && strstr(msg, "mu[1]"),
         "invalid mu[1]: st %d msg '%s'", st, msg);
   CHECK(wa_critical_sweep(WA_MODEL_DW, 0.3, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL, 0) == WA_OK,
         "empty sweep");
   CHECK(wa_critical_sweep(WA_MODEL_DW, -0.3, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL, 0) ==
            WA_INVALID_ARGUMENT,
         "empty sweep still validates alpha");
   CHECK(wa_critical_sweep(WA_MODEL_DW, 0.3, -1, mu, fc, pf, fm, pm, NULL, NULL, 0) == WA_INVALID_ARGUMENT,
         "n_mu < 0");
   CHECK(wa_critical_sweep(WA_MODEL_DW, 0.3, 3, NULL, fc, pf, fm, pm, NULL, NULL, 0) == WA_INVALID_ARGUMENT,
         "NULL mu");
   CHECK(wa_critical_sweep(WA_MODEL_DW, 0.3, 3, mu, fc, pf, fm, NULL, NULL, NULL, 0) == WA_INVALID_ARGUMENT,
         "NULL pf_mechanism");
   CHECK(wa_critical_sweep(8, 0.3, 3, mu, fc, pf, fm, pm, NULL, NULL, 0) == WA_INVALID_ARGUMENT, "model 8");
}

/* A sweep never loses work (issue 9): each row equals wa_critical_forces at its mu, a
   row that fails there holds NaN, -1 and that status in row_status, every other row is
   written, and the sweep returns the status of the first failing row. The MD mu values
   surround a mechanism change at alpha = 1 where the tracer failed (issue 9 item 4); the
   checks hold whether or not a row fails. */
static void test_sweep_keeps_rows(void) {
   double mu[6] = {0.5, 0.7936921, 0.79369860901363931, 0.7937005, 0.9, 2.0};
   double fc[6], pf[6];
   int fm[6], pm[6], rs[6], st, i, first = WA_OK, n_failed = 0;
   char msg[256];
   st = wa_critical_sweep_status(WA_MODEL_MD, 1.0, 6, mu, fc, pf, fm, pm, rs, msg,
                                 sizeof msg);
   for (i = 0; i < 6; i++) {
      double f1, p1;
      int s1 = wa_critical_forces(WA_MODEL_MD, 1.0, mu[i], &f1, &p1, NULL, 0);
      CHECK(rs[i] == s1, "md row %d: row_status %d, wa_critical_forces %d", i, rs[i], s1);
      if (s1 == WA_OK) {
         CHECK(fc[i] == f1 && pf[i] == p1 && fm[i] >= 0 && pm[i] >= 0,
               "md row %d (mu %.17g) written", i, mu[i]);
      } else {
         CHECK(isnan(fc[i]) && isnan(pf[i]) && fm[i] == -1 && pm[i] == -1,
               "md row %d (mu %.17g) failed: NaN and -1", i, mu[i]);
         if (first == WA_OK) first = s1;
         n_failed++;
      }
   }
   CHECK(st == first, "sweep returns the first row's failure: %d vs %d", st, first);
   if (n_failed > 0)
      CHECK(strstr(msg, "rows failed") != NULL, "failing sweep message: '%s'", msg);
   else
      CHECK(msg[0] == '\0', "clean sweep: empty message '%s'", msg);
   printf("  md alpha 1 sweep around the mechanism change: %d of 6 rows failed\n", n_failed);

   /* every row ok: row_status all WA_OK, same numbers as wa_critical_sweep */
   {
      double mu2[3] = {0.1, 1.0, 5.0}, fc2[3], pf2[3];
      int fm2[3], pm2[3];
      st = wa_critical_sweep_status(WA_MODEL_DW, 0.3, 3, mu2, fc, pf, fm, pm, rs, NULL, 0);
      wa_critical_sweep(WA_MODEL_DW, 0.3, 3, mu2, fc2, pf2, fm2, pm2, NULL, NULL, 0);
      CHECK(st == WA_OK && rs[0] == WA_OK && rs[1] == WA_OK && rs[2] == WA_OK &&
               fc[2] == fc2[2] && pf[1] == pf2[1] && fm[2] == fm2[2],
            "dw sweep_status: st %d rows %d %d %d", st, rs[0], rs[1], rs[2]);
      mu2[1] = NAN;
      st = wa_critical_sweep_status(WA_MODEL_DW, 0.3, 3, mu2, fc, pf, fm, pm, rs, msg,
                                    sizeof msg);
      CHECK(st == WA_INVALID_ARGUMENT && rs[0] == WA_INVALID_ARGUMENT &&
               rs[2] == WA_INVALID_ARGUMENT && isnan(fc[0]) && strstr(msg, "mu[1]"),
            "NaN mu[1]: every row invalid, st %d msg '%s'", st, msg);
      mu2[1] = 1.0;
      CHECK(wa_critical_sweep_status(WA_MODEL_DW, 0.3, 3, mu2, fc, pf, fm, pm, NULL, msg,
                                     sizeof msg) == WA_INVALID_ARGUMENT &&
               strstr(msg, "row_status"),
            "NULL row_status: '%s'", msg);
      CHECK(wa_critical_sweep_status(WA_MODEL_DW, 0.3, 0, NULL, NULL, NULL, NULL, NULL, NULL,
                                     NULL, 0) == WA_OK,
            "empty sweep_status");
   }
}

/* 4 threads tracing branches and computing critical forces at once get the serial
   results bit for bit. */
#define N_BRANCH_JOBS 6
typedef struct {
   int model;
   double mu;
   branch_buf b;
   double fc, pf;
   int st;
} branch_job;

static void *run_branch_job(void *arg) {
   branch_job *job = (branch_job *)arg;
   trace(job->model, 0.3, job->mu, &job->b);
   job->st = wa_critical_forces(job->model, 0.3, job->mu, &job->fc, &job->pf, NULL, 0);
   return NULL;
}

static int same_branch(const branch_job *x, const branch_job *y) {
   int n = x->b.n;
   if (x->b.st != y->b.st || n != y->b.n || x->st != y->st) return 0;
   if (memcmp(&x->fc, &y->fc, sizeof x->fc) || memcmp(&x->pf, &y->pf, sizeof x->pf)) return 0;
   if (n <= 0) return 1;
   return memcmp(x->b.a, y->b.a, n * sizeof(double)) == 0 &&
          memcmp(x->b.c, y->b.c, n * sizeof(double)) == 0 &&
          memcmp(x->b.p, y->b.p, n * sizeof(double)) == 0 &&
          memcmp(x->b.z, y->b.z, n * sizeof(int)) == 0 &&
          memcmp(x->b.s, y->b.s, n * sizeof(int)) == 0 &&
          memcmp(x->b.e, y->b.e, n * sizeof(int)) == 0;
}

static void test_branch_threads(void) {
   static branch_job serial[N_BRANCH_JOBS], threaded[4][N_BRANCH_JOBS];
   static const double mus[3] = {1.0, 3.0, 5.0};
   pthread_t tid[4 * N_BRANCH_JOBS];
   int j, t;
   for (j = 0; j < N_BRANCH_JOBS; j++) {
      serial[j].model = j < 3 ? WA_MODEL_DW : WA_MODEL_MD;
      serial[j].mu = mus[j % 3];
      run_branch_job(&serial[j]);
      for (t = 0; t < 4; t++) {
         threaded[t][j].model = serial[j].model;
         threaded[t][j].mu = serial[j].mu;
      }
   }
   for (j = 0; j < N_BRANCH_JOBS; j++)      /* 4 threads on each job at once */
      for (t = 0; t < 4; t++)
         CHECK(pthread_create(&tid[4 * j + t], NULL, run_branch_job, &threaded[t][j]) == 0,
               "pthread_create");
   for (t = 0; t < 4 * N_BRANCH_JOBS; t++) pthread_join(tid[t], NULL);
   for (j = 0; j < N_BRANCH_JOBS; j++)
      for (t = 0; t < 4; t++)
         CHECK(serial[j].b.st == WA_OK && same_branch(&serial[j], &threaded[t][j]),
               "branch job %d thread %d: results differ from the serial ones", j, t);
}

/* wa_version() is the text of the file VERSION (the one source of the version number). */
static void test_version(void) {
   char want[64] = "";
   FILE *f = fopen("VERSION", "r");
   const char *v = wa_version();
   CHECK(f != NULL, "VERSION file readable from the repository root");
   if (f != NULL) {
      if (fgets(want, (int)sizeof want, f) == NULL) want[0] = '\0';
      fclose(f);
      want[strcspn(want, "\r\n \t")] = '\0';
   }
   CHECK(v != NULL && strcmp(v, want) == 0, "wa_version() = \"%s\", VERSION = \"%s\"",
         v ? v : "(null)", want);
}

/* wa_adhesion_map: DW over three alpha gives the boundaries 101 and 212 at alpha = 0.01
   (where mechanism_change puts them, 1.8099 and 43.589), each curve in increasing alpha;
   capacity too small writes only what fits; invalid input gives *n_out = 0. */
static void test_adhesion_map(void) {
   const double alpha[3] = {0.01, 0.0102, 0.0104};
   int code[512], n = -1, st, i, saw101 = 0, saw212 = 0, small[2];
   double a[512], m[512], as[2], ms[2];
   st = wa_adhesion_map(WA_MODEL_DW, WA_MAP_CONTROL_LOAD, 3, alpha, 1e-3, 1e3, 60, 512, code, a, m, &n, NULL, 0);
   CHECK(st == WA_OK && n >= 9, "adhesion_map: status %d, %d points", st, n);
   for (i = 0; i < n && i < 512; i++) {
      if (code[i] == 101 && a[i] == 0.01) saw101 = close_to(m[i], 1.8098847396573090, 1e-8);
      if (code[i] == 212 && a[i] == 0.01) saw212 = close_to(m[i], 43.588507907118696, 1e-8);
      if (i > 0 && code[i] == code[i - 1] && a[i] > a[i - 1] == 0 && a[i] != 0.01)
         CHECK(0, "adhesion_map: alpha increases along a curve (point %d)", i);
   }
   CHECK(saw101 && saw212, "adhesion_map: 101 at mu 1.80988, 212 at mu 43.5885");
   st = wa_adhesion_map(WA_MODEL_DW, WA_MAP_CONTROL_LOAD, 3, alpha, 1e-3, 1e3, 60, 2, small, as, ms, &n, NULL, 0);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n >= 9, "adhesion_map capacity 2: %d, %d", st, n);
   st = wa_adhesion_map(WA_MODEL_JKR, WA_MAP_CONTROL_LOAD, 3, alpha, 1e-3, 1e3, 60, 512, code, a, m, &n, NULL, 0);
   CHECK(st == WA_INVALID_ARGUMENT && n == 0, "adhesion_map jkr refused");
   st = wa_adhesion_map(WA_MODEL_DW, WA_MAP_CONTROL_LOAD, 0, alpha, 1e-3, 1e3, 60, 512, code, a, m, &n, NULL, 0);
   CHECK(st == WA_INVALID_ARGUMENT && n == 0, "adhesion_map n_alpha 0 refused");
   st = wa_adhesion_map(WA_MODEL_DW, WA_MAP_CONTROL_LOAD, 3, alpha, 1e3, 1e-3, 60, 512, code, a, m, &n, NULL, 0);
   CHECK(st == WA_INVALID_ARGUMENT && n == 0, "adhesion_map mu_lo > mu_hi refused");
   st = wa_adhesion_map(WA_MODEL_DW, WA_MAP_CONTROL_LOAD, 3, alpha, 1e-3, 1e3, 60, 512, NULL, a, m, &n, NULL, 0);
   CHECK(st == WA_INVALID_ARGUMENT && n == 0, "adhesion_map NULL code refused");
   st = wa_adhesion_map(WA_MODEL_DW, WA_MAP_CONTROL_LOAD, 3, NULL, 1e-3, 1e3, 60, 512, code, a, m, &n, NULL, 0);
   CHECK(st == WA_INVALID_ARGUMENT && n == 0, "adhesion_map NULL alpha refused");
   st = wa_adhesion_map(WA_MODEL_DW, WA_MAP_CONTROL_LOAD, 3, alpha, 1e-3, 1e3, 60, 512, code, a, m, NULL, NULL, 0);
   CHECK(st == WA_INVALID_ARGUMENT, "adhesion_map NULL n_out refused");
}

/* wa_adhesion_map_control: gap control over DW alpha 0.3, 0.31 gives only the retraction
   boundary 401 (gradual -> jump-out), at alpha 0.3 at mu 2.34035 (where
   gap_mechanism_change puts it, to 1e-8 relative); control 4
   is refused; WA_MAP_CONTROL_LOAD gives what wa_adhesion_map gives. */
static void test_adhesion_map_control(void) {
   const double alpha[2] = {0.3, 0.31};
   int code[256], code2[256], n = -1, n2 = -1, st, i, saw401 = 0, only_gap = 1;
   double a[256], m[256], a2[256], m2[256];
   st = wa_adhesion_map_control(WA_MODEL_DW, WA_MAP_CONTROL_GAP, 2, alpha, 1e-2, 1e2, 256,
                                code, a, m, &n);
   CHECK(st == WA_OK && n >= 2, "adhesion_map_control gap: status %d, %d points", st, n);
   for (i = 0; i < n && i < 256; i++) {
      if (code[i] < 300) only_gap = 0;
      if (code[i] == 401 && a[i] == 0.3) saw401 = close_to(m[i], 2.3403548179, 1e-8);
   }
   CHECK(only_gap && saw401, "adhesion_map_control gap: 401 at mu 2.34035, gap codes only");
   st = wa_adhesion_map_control(WA_MODEL_DW, 4, 2, alpha, 1e-2, 1e2, 256, code, a, m, &n);
   CHECK(st == WA_INVALID_ARGUMENT && n == 0, "adhesion_map_control control 4 refused");
   st = wa_adhesion_map_control(WA_MODEL_DW, WA_MAP_CONTROL_LOAD, 2, alpha, 1e-2, 1e2, 256,
                                code, a, m, &n);
   CHECK(st == WA_OK, "adhesion_map_control load: status %d", st);
   st = wa_adhesion_map(WA_MODEL_DW, WA_MAP_CONTROL_LOAD, 2, alpha, 1e-2, 1e2, 60, 256, code2, a2, m2, &n2, NULL, 0);
   CHECK(st == WA_OK && n2 == n, "adhesion_map_control load = adhesion_map (%d, %d)", n, n2);
   for (i = 0; i < n && i < n2 && i < 256; i++)
      if (code[i] != code2[i] || a[i] != a2[i] || m[i] != m2[i]) {
         CHECK(0, "adhesion_map_control load differs at point %d", i);
         break;
      }
}

/* ---------------------------------------------------------------- separation */

/* Mean over one period of f sampled at n midpoints of [-1/2, 1/2]. */
static double period_mean(const double *f, int n) {
   double s = 0.0;
   int i;
   for (i = 0; i < n; i++) s += f[i];
   return s / n;
}

/* wa_equilibrium_gap, wa_roots_gap and wa_trace_branch_gap agree with the plain functions
   and with the closed forms (Westergaard: 1 - A^2 + A^2 ln A^2; JKR: 1 - A^2 + P* ln A^2). */
static void test_gap_functions(void) {
   double c, p, g, c0, p0, cs[8], ps[8], gs[8];
   int z, z0, zs[8], n, m, k, st;
   char msg[256];
   for (m = 0; m < 4; m++) {
      double a;
      for (a = 0.05; a < 0.5; a += 0.1) {
         st = wa_equilibrium_gap(models[m], 0.3, 1.0, a, &c, &p, &z, &g);
         wa_equilibrium(models[m], 0.3, 1.0, a, &c0, &p0, &z0, NULL, NULL, 0);
         CHECK(st == WA_OK && c == c0 && p == p0 && z == z0 && isfinite(g) && g >= 0,
               "equilibrium_gap model %d a* %g: status %d gbar %g", m, a, st, g);
         st = wa_roots_gap(models[m], 0.3, 1.0, a, 8, cs, ps, zs, gs, &n);
         CHECK(st == WA_OK && n >= 1 && close_to(cs[0], c, 1e-12) && close_to(gs[0], g, 1e-12),
               "roots_gap model %d a* %g: status %d n %d gbar %.17g vs %.17g", m, a, st, n, gs[0], g);
         for (k = 0; k < n && st == WA_OK; k++)
            CHECK(isfinite(gs[k]) && gs[k] >= 0, "roots_gap model %d root %d gbar %g", m, k,
                  gs[k]);
         if (m == 0) {
            double s2 = sin(pi * a) * sin(pi * a);
            CHECK(close_to(g, 1 - s2 + s2 * log(s2), 1e-14), "westergaard gbar(%g) = %.17g", a,
                  g);
         } else if (m == 1) {
            double s2 = sin(pi * a) * sin(pi * a);
            CHECK(close_to(g, 1 - s2 + p * log(s2), 1e-13), "jkr gbar(%g) = %.17g", a, g);
         }
      }
      st = wa_equilibrium_gap(models[m], 0.3, 1.0, 0.5, &c, &p, &z, &g);
      CHECK(st == WA_OK && g == 0.0, "full contact: gbar %g (status %d)", g, st);
   }
   /* failure outputs and NULL */
   c = p = g = 1.0;
   z = 7;
   st = wa_equilibrium_gap_msg(WA_MODEL_DW, 0.3, 1.0, 0.7, &c, &p, &z, &g, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && isnan(c) && isnan(p) && isnan(g) && z == 0 &&
            strstr(msg, "a_star"), "equilibrium_gap a* 0.7: %d '%s'", st, msg);
   c = p = 1.0;
   st = wa_equilibrium_gap_msg(WA_MODEL_DW, 0.3, 1.0, 0.2, &c, &p, &z, NULL, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && isnan(c) && isnan(p) && strstr(msg, "gbar"),
         "equilibrium_gap gbar NULL: %d '%s'", st, msg);
   n = 5;
   st = wa_roots_gap_msg(WA_MODEL_MD, 0.3, 1.0, 0.2, 8, cs, ps, zs, NULL, &n, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && n == 0 && strstr(msg, "gbar"), "roots_gap gbar NULL: %d",
         st);
   st = wa_roots_gap(WA_MODEL_MD, 0.3, 1.0, 0.2, 0, NULL, NULL, NULL, NULL, &n);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n >= 1, "roots_gap capacity 0: %d n %d", st, n);
   /* DW at a* = 0: no contact, no mean gap */
   st = wa_equilibrium_gap_msg(WA_MODEL_DW, 0.3, 1.0, 0.0, &c, &p, &z, &g, msg, sizeof msg);
   CHECK((st == WA_OK && isfinite(g) && g >= 0) || (st == WA_NO_SOLUTION && isnan(g)),
         "dw a* = 0: status %d gbar %g '%s'", st, g, msg);
   {
      enum { CAP = 4000 };
      static double a1[CAP], c1[CAP], p1[CAP], g1[CAP], a2[CAP], c2[CAP], p2[CAP];
      static int z1[CAP], s1[CAP], e1[CAP], z2[CAP], s2[CAP], e2[CAP];
      int n1, n2, same = 1, ok = 1;
      for (m = 0; m < 4; m++) {
         int st1 = wa_trace_branch_gap(models[m], 0.3, 1.0, CAP, a1, c1, p1, z1, s1, e1, g1,
                                       &n1);
         int st2 = wa_trace_branch(models[m], 0.3, 1.0, CAP, a2, c2, p2, z2, s2, e2, NULL, &n2, NULL, 0);
         CHECK(st1 == WA_OK && st2 == WA_OK && n1 == n2, "branch_gap model %d: %d %d n %d %d",
               m, st1, st2, n1, n2);
         for (k = 0; k < n1 && k < n2; k++) {
            same = same && a1[k] == a2[k] && c1[k] == c2[k] && p1[k] == p2[k] &&
                   e1[k] == e2[k];
            ok = ok && isfinite(g1[k]) && g1[k] >= 0 && g1[k] <= 1.5;
         }
         CHECK(same && ok, "branch_gap model %d: same points %d, gbar in [0, 1.5] %d", m, same,
               ok);
         CHECK(g1[n1 - 1] < 1e-6, "branch_gap model %d: gbar at the end %g", m, g1[n1 - 1]);
         /* the mean gap of each point is its state's: check a few against roots_gap */
         for (k = 1; k < n1 - 1; k += n1 / 7) {
            int j, nr, found = 0;
            if (z1[k] == WA_ZONE_FULL_CONTACT) continue;
            if (wa_roots_gap(models[m], 0.3, 1.0, a1[k], 8, cs, ps, zs, gs, &nr) != WA_OK)
               continue;
            for (j = 0; j < nr; j++)
               if (fabs(cs[j] - c1[k]) < 1e-7 && close_to(gs[j], g1[k], 1e-6)) found = 1;
            CHECK(found, "branch_gap model %d point %d: a* %.17g c* %.17g gbar %.17g not among "
                  "roots", m, k, a1[k], c1[k], g1[k]);
         }
      }
      st = wa_trace_branch_gap_msg(WA_MODEL_DW, 0.3, 1.0, 8, a1, c1, p1, z1, s1, e1, NULL, &n1,
                                   msg, sizeof msg);
      CHECK(st == WA_INVALID_ARGUMENT && n1 == 0 && strstr(msg, "gbar"),
            "branch_gap gbar NULL: %d '%s'", st, msg);
      st = wa_trace_branch_gap(WA_MODEL_DW, 0.3, 1.0, 0, NULL, NULL, NULL, NULL, NULL, NULL,
                               NULL, &n1);
      CHECK(st == WA_CAPACITY_TOO_SMALL && n1 > 2, "branch_gap capacity 0: %d n %d", st, n1);
   }
}

/* wa_profile: identities (traction mean = P*, gap = 0 on the contact and >= 0, gap mean =
   gbar, MD h(c) = 2 Dcod), values of test/data/separation_*.txt, and the refusals. */
static void test_profile(void) {
   enum { N = 20000 };
   static double x[N], t[N], h[N];
   double cs[8], ps[8], gs[8], c, p, g;
   int zs[8], z, n, m, k, i, st;
   char msg[256];
   for (i = 0; i < N; i++) x[i] = -0.5 + (i + 0.5) / N;
   for (m = 0; m < 4; m++) {
      double a;
      for (a = 0.1; a < 0.45; a += 0.1) {
         st = wa_roots_gap(models[m], 0.3, 1.0, a, 8, cs, ps, zs, gs, &n);
         for (k = 0; k < n && st == WA_OK; k++) {
            int ok = 1, on_contact = 1;
            int sp = wa_profile(models[m], 0.3, 1.0, a, cs[k], N, x, t, h, NULL, 0);
            CHECK(sp == WA_OK, "profile model %d a* %g root %d: status %d", m, a, k, sp);
            if (sp != WA_OK) continue;
            for (i = 0; i < N; i++) {
               ok = ok && isfinite(t[i]) && isfinite(h[i]) && h[i] >= 0;
               if (fabs(x[i]) < a) on_contact = on_contact && h[i] == 0.0;
            }
            CHECK(ok && on_contact, "profile model %d a* %g root %d: finite %d, h = 0 on the "
                  "contact %d", m, a, k, ok, on_contact);
            /* midpoint rule: the square-root edges limit it to ~1e-4 (JKR ~1e-2) */
            CHECK(fabs(period_mean(t, N) - ps[k]) < (m == 1 ? 2e-2 : 1e-3),
                  "profile model %d a* %g root %d: mean traction %.9g vs P* %.9g", m, a, k,
                  period_mean(t, N), ps[k]);
            CHECK(fabs(period_mean(h, N) - gs[k]) < 1e-6,
                  "profile model %d a* %g root %d: mean gap %.12g vs gbar %.12g", m, a, k,
                  period_mean(h, N), gs[k]);
            if (m == WA_MODEL_MD && zs[k] == WA_ZONE_INSIDE) {
               double dcod = cbrt(pow(0.3, 4) / 2) / 1.0, xc = cs[k], hc;
               wa_profile(models[m], 0.3, 1.0, a, cs[k], 1, &xc, t, &hc, NULL, 0);
               CHECK(close_to(hc, 2 * dcod, 1e-10), "md h(c*) %.17g vs 2 Dcod %.17g", hc,
                     2 * dcod);
            }
         }
      }
   }
   /* values of tools/reference/make_separation_reference.py (test/data/separation_*.txt rows) */
   {
      double xs = 0.36, tt, hh;
      st = wa_profile(WA_MODEL_MD, 0.01, 0.001, 0.3, 0.5, 1, &xs, &tt, &hh, NULL, 0);
      CHECK(st == WA_OK && close_to(tt, -4.5930363226678917957e-5, 1e-12) &&
               close_to(hh, 0.1023641757601853788, 1e-12),
            "md reference row: status %d traction %.17g gap %.17g", st, tt, hh);
   }
   /* MD without contact (a* = 0): a Dugdale zone around the crest */
   {
      double xs[3] = {0.0, 0.05, 0.3}, tt[3], hh[3], dcod = cbrt(pow(0.3, 4) / 2);
      st = wa_profile(WA_MODEL_MD, 0.3, 1.0, 0.0, 0.05, 3, xs, tt, hh, NULL, 0);
      CHECK(st == WA_OK && tt[0] < 0 && tt[2] == 0 && close_to(hh[1], 2 * dcod, 1e-12) &&
               hh[0] > 0 && hh[0] < hh[1] && hh[2] > hh[1],
            "md no contact: status %d traction %g %g gap %g %g %g", st, tt[0], tt[2], hh[0],
            hh[1], hh[2]);
      st = wa_profile_msg(WA_MODEL_MD, 0.3, 1.0, 0.0, 0.5, 3, xs, tt, hh, msg, sizeof msg);
      CHECK(st == WA_NO_SOLUTION && isnan(tt[0]) && isnan(hh[2]) && strstr(msg, "c_star"),
            "md a* = 0, c* = 1/2: %d '%s'", st, msg);
   }
   /* refusals: no state with that c*, bad arguments; NaN in every output element */
   {
      double xs[2] = {0.1, 0.2}, tt[2], hh[2];
      wa_equilibrium_gap(WA_MODEL_DW, 0.3, 1.0, 0.2, &c, &p, &z, &g);
      st = wa_profile(WA_MODEL_DW, 0.3, 1.0, 0.2, c + 1e-7, 2, xs, tt, hh, NULL, 0);
      CHECK(st == WA_OK, "profile within 1e-6 of c*: status %d", st);
      st = wa_profile_msg(WA_MODEL_DW, 0.3, 1.0, 0.2, c + 1e-3, 2, xs, tt, hh, msg, sizeof msg);
      CHECK(st == WA_NO_SOLUTION && isnan(tt[0]) && isnan(tt[1]) && isnan(hh[0]) &&
               isnan(hh[1]) && strstr(msg, "nearest"),
            "profile c* off by 1e-3: %d '%s'", st, msg);
      st = wa_profile_msg(WA_MODEL_WESTERGAARD, 0.3, 1.0, 0.2, 0.3, 2, xs, tt, hh, msg,
                          sizeof msg);
      CHECK(st == WA_NO_SOLUTION, "westergaard c* != a*: %d '%s'", st, msg);
      st = wa_profile_msg(WA_MODEL_JKR, 0.3, 1.0, 0.5, 0.5, 2, xs, tt, hh, msg, sizeof msg);
      CHECK(st == WA_NO_SOLUTION && strstr(msg, "jkr"), "jkr full contact: %d '%s'", st, msg);
      st = wa_profile_msg(WA_MODEL_DW, 0.3, 1.0, 0.0, 0.1, 2, xs, tt, hh, msg, sizeof msg);
      CHECK(st == WA_NO_SOLUTION && strstr(msg, "dw"), "dw a* = 0: %d '%s'", st, msg);
      st = wa_profile_msg(WA_MODEL_DW, 0.3, 1.0, 0.2, 0.7, 2, xs, tt, hh, msg, sizeof msg);
      CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "c_star"), "c* 0.7: %d '%s'", st, msg);
      st = wa_profile_msg(WA_MODEL_DW, 0.3, 1.0, 0.2, c, -1, xs, tt, hh, msg, sizeof msg);
      CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "n ="), "n = -1: %d '%s'", st, msg);
      st = wa_profile_msg(WA_MODEL_DW, 0.3, 1.0, 0.2, c, 2, NULL, tt, hh, msg, sizeof msg);
      CHECK(st == WA_INVALID_ARGUMENT && isnan(tt[1]) && strstr(msg, "x_star"),
            "x_star NULL: %d '%s'", st, msg);
      xs[1] = NAN;
      st = wa_profile_msg(WA_MODEL_DW, 0.3, 1.0, 0.2, c, 2, xs, tt, hh, msg, sizeof msg);
      CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "x_star[1]"), "x NaN: %d '%s'", st, msg);
      st = wa_profile(WA_MODEL_DW, 0.3, 1.0, 0.2, c, 0, NULL, NULL, NULL, NULL, 0);
      CHECK(st == WA_OK, "n = 0 identifies the state: %d", st);
      st = wa_profile_msg(7, 0.3, 1.0, 0.2, c, 0, NULL, NULL, NULL, msg, sizeof msg);
      CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "model"), "model 7: %d '%s'", st, msg);
   }
   /* JKR: -Infinity exactly at the contact edge, finite elsewhere */
   {
      double xs[3] = {0.2, -0.2, 0.1}, tt[3], hh[3];
      st = wa_profile(WA_MODEL_JKR, 0.3, 1.0, 0.2, 0.2, 3, xs, tt, hh, NULL, 0);
      CHECK(st == WA_OK && tt[0] == -INFINITY && tt[1] == -INFINITY && isfinite(tt[2]) &&
               hh[0] == 0, "jkr edge: %d %g %g %g", st, tt[0], tt[1], tt[2]);
   }
}

/* Gap control: wa_gap_path (the events `wavyadhesion path --control gap --model md
   --alpha 0.3 --mu 1` prints), wa_gap_law against the path's events and the Westergaard
   closed form, wa_gap_critical against both and against P_pf; capacity, NULL pointers
   and invalid arguments with the failure values written. */
static void test_gap_path(void) {
   static const int want_stage[14] = {1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 2};
   static const int want_event[14] = {10, 3, 4, 11, 3, 4, 5, 6, 3, 4, 12, 3, 4, 13};
   double a[16], c[16], p[16], g[16], w = -1, wf = -1, gt = -1;
   int stage[16], ev[16], zc[16], n = -1, k, st, m, same = 1;
   char msg[256];
   st = wa_gap_path(WA_MODEL_MD, 0.3, 1.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0);
   CHECK(st == WA_OK && n == 14, "md gap path (0.3, 1): st %d n %d (want 14)", st, n);
   for (k = 0; k < 14 && n == 14; k++)
      same = same && stage[k] == want_stage[k] && ev[k] == want_event[k];
   CHECK(same, "md gap path: stages and events as the CLI prints them");
   CHECK(n == 14 && close_to(gt, 1.3187975707547834, 1e-12) && g[0] == gt &&
            close_to(p[3], -9.0116543396273133e-02, 1e-10) && zc[3] == WA_ZONE_NO_CONTACT &&
            close_to(g[13], 1.4080166215419854, 1e-10) && g[1] == g[0] && close_to(g[8], g[9], 1e-10) &&
            close_to(p[6], 5.5654721873560731e-01, 1e-12) && g[6] == 0.0,
         "md gap path values: g_touch %.17g P %.17g g %.17g", gt, p[3], g[13]);
   CHECK(w > 0 && close_to(wf, w / (pi * 0.3 * 0.3 / 2), 1e-14), "W* %g, fraction %g", w, wf);
   for (k = 0; k < 16; k++) {
      a[k] = -7;
      ev[k] = -7;
   }
   st = wa_gap_path(WA_MODEL_MD, 0.3, 1.0, 3, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n == 14 && ev[2] == 4 && ev[3] == -7 && a[3] == -7 &&
            w > 0 && close_to(gt, 1.3187975707547834, 1e-12),
         "gap path capacity 3: st %d n %d", st, n);
   st = wa_gap_path(WA_MODEL_WESTERGAARD, 0.3, 1.0, 0, NULL, NULL, NULL, NULL, NULL, NULL,
                    NULL, &n, &w, &wf, &gt, NULL, 0);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n == 6 && w == 0.0 && wf == 0.0 && gt == 1.0,
         "westergaard gap path count: st %d n %d W* %g g_touch %g", st, n, w, gt);
   st = wa_gap_path(WA_MODEL_WESTERGAARD, 0.3, 1.0, 16, stage, ev, zc, a, c, p, g, &n, &w,
                    &wf, &gt, NULL, 0);
   CHECK(st == WA_OK && n == 6 && ev[3] == WA_GAP_EVENT_CONTACT_LOST && g[3] == 1.0 &&
            stage[3] == WA_STAGE_RETRACTION && ev[0] == WA_GAP_EVENT_TOUCH,
         "westergaard gap path: contact lost at gbar* = 1");
   for (m = 0; m < 4; m++) {
      int md = models[m];
      st = wa_gap_path(md, 0.3, 5.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0);
      CHECK(st == WA_OK && n >= 6 && ev[0] == WA_GAP_EVENT_TOUCH &&
               ev[n - 1] == WA_GAP_EVENT_INTERACTION_LOST && w >= 0,
            "model %d gap path (0.3, 5): st %d n %d", md, st, n);
      for (k = 0; k < n && st == WA_OK; k++)
         if (ev[k] == WA_GAP_EVENT_JUMP_START)
            CHECK(k + 1 < n && ev[k + 1] == WA_GAP_EVENT_JUMP_END && close_to(g[k + 1], g[k], 1e-10),
                  "model %d: jump %d keeps gbar*", md, k);
      n = 3;
      w = wf = gt = 0;
      CHECK(wa_gap_path(md, 0.3, 1.0, 16, stage, ev, zc, a, c, p, g, NULL, &w, &wf, &gt, NULL, 0) ==
               WA_INVALID_ARGUMENT && isnan(w) && isnan(wf) && isnan(gt),
            "NULL n_events");
      CHECK(wa_gap_path(md, 0.3, 1.0, 16, stage, ev, zc, a, c, p, g, &n, NULL, &wf, &gt, NULL, 0) ==
               WA_INVALID_ARGUMENT && n == 0 && isnan(wf) && isnan(gt),
            "NULL W_star");
      CHECK(wa_gap_path(md, 0.3, 1.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, NULL, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "NULL g_touch");
      CHECK(wa_gap_path(md, 0.3, 1.0, 16, stage, ev, NULL, a, c, p, g, &n, &w, &wf, &gt, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "NULL zone_case");
      CHECK(wa_gap_path(md, 0.3, 1.0, 16, stage, ev, zc, a, c, p, NULL, &n, &w, &wf, &gt, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "NULL gbar");
      CHECK(wa_gap_path(md, 0.3, 1.0, -1, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "capacity -1");
      n = 3;
      CHECK(wa_gap_path(md, 0.0, 1.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0) ==
               WA_INVALID_ARGUMENT && n == 0 && isnan(w) && isnan(gt),
            "model %d alpha = 0", md);
      CHECK(wa_gap_path(md, 0.3, -1.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "mu < 0");
      CHECK(wa_gap_path(md, NAN, 1.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0) ==
               WA_INVALID_ARGUMENT,
            "alpha NaN");
   }
   CHECK(wa_gap_path(7, 0.3, 1.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0) ==
            WA_INVALID_ARGUMENT,
         "model 7");
   st = wa_gap_path_msg(WA_MODEL_MD, 0.3, 1.0, 3, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt,
                        msg, sizeof msg);
   CHECK(st == WA_CAPACITY_TOO_SMALL && strstr(msg, "14 events"), "gap path message: '%s'",
         msg);
   st = wa_gap_path_msg(WA_MODEL_MD, 0.3, -2.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf,
                        &gt, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "mu"), "gap path mu message: '%s'", msg);
   st = wa_gap_path_msg(WA_MODEL_DW, 0.3, 1.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt,
                        msg, sizeof msg);
   CHECK(st == WA_OK && msg[0] == '\0', "empty message on success");
}

static void test_gap_law(void) {
   double gb[8], pa[8], pr[8], da[8], dr[8], a[16], c[16], p[16], g[16], w, wf, gt;
   int stage[16], ev[16], zc[16], n, k, st;
   char msg[256];
   /* Westergaard: gbar* = 1 - P + P ln P on approach and retraction alike */
   for (k = 0; k < 6; k++) gb[k] = 0.1 + 0.15 * k;
   gb[6] = 1.5;
   gb[7] = 0.0;
   st = wa_gap_law(WA_MODEL_WESTERGAARD, 0.3, 1.0, 8, gb, pa, pr, da, dr, NULL, 0);
   CHECK(st == WA_OK, "westergaard gap law: st %d", st);
   for (k = 0; k < 6 && st == WA_OK; k++)
      CHECK(pa[k] == pr[k] && close_to(1 - pa[k] + pa[k] * log(pa[k]), gb[k], 1e-9),
            "westergaard gap law at %g: P %.17g", gb[k], pa[k]);
   CHECK(pa[6] == 0 && pr[6] == 0 && da[6] == 0 && pa[7] == 1.0 && isinf(da[7]) && da[7] < 0,
         "westergaard: P* = 0 apart, full contact at gbar* = 0");
   /* MD: the law at the gbar* of retraction events that are not jumps gives their P* */
   st = wa_gap_path(WA_MODEL_MD, 0.3, 1.0, 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0);
   gb[0] = g[10];       /* contact lost (gradual) */
   gb[1] = g[3];        /* contact made on approach (gradual) */
   gb[2] = 0.5 * (g[0] + g[13]);   /* between touch and interaction lost: apart on approach */
   st = wa_gap_law(WA_MODEL_MD, 0.3, 1.0, 3, gb, pa, pr, da, dr, NULL, 0);
   CHECK(st == WA_OK && close_to(pr[0], p[10], 1e-9) && close_to(pa[1], p[3], 1e-9) &&
            pa[2] == 0.0 && pr[2] < 0.0,
         "md gap law at the events: %.17g %.17g / %.17g %.17g", pr[0], p[10], pa[1], p[3]);
   /* n = 0 checks the arguments only; failures write NaN everywhere */
   CHECK(wa_gap_law(WA_MODEL_DW, 0.3, 1.0, 0, NULL, NULL, NULL, NULL, NULL, NULL, 0) == WA_OK, "n = 0");
   CHECK(wa_gap_law(WA_MODEL_DW, -0.3, 1.0, 0, NULL, NULL, NULL, NULL, NULL, NULL, 0) ==
            WA_INVALID_ARGUMENT,
         "n = 0 still checks alpha");
   CHECK(wa_gap_law(WA_MODEL_DW, 0.3, 1.0, -1, gb, pa, pr, da, dr, NULL, 0) == WA_INVALID_ARGUMENT,
         "n = -1");
   gb[0] = 0.5;
   gb[1] = -0.25;
   pa[0] = pr[0] = da[0] = dr[0] = 3;
   st = wa_gap_law_msg(WA_MODEL_DW, 0.3, 1.0, 2, gb, pa, pr, da, dr, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "gbar[1]") && isnan(pa[0]) && isnan(pr[0]) &&
            isnan(da[0]) && isnan(dr[1]),
         "gbar[1] < 0: st %d '%s'", st, msg);
   gb[1] = NAN;
   st = wa_gap_law_msg(WA_MODEL_DW, 0.3, 1.0, 2, gb, pa, pr, da, dr, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "gbar[1]"), "gbar[1] NaN: '%s'", msg);
   gb[1] = INFINITY;
   CHECK(wa_gap_law(WA_MODEL_DW, 0.3, 1.0, 2, gb, pa, pr, da, dr, NULL, 0) == WA_INVALID_ARGUMENT,
         "gbar[1] infinite");
   gb[1] = 0.25;
   pa[0] = 3;
   CHECK(wa_gap_law(WA_MODEL_DW, 0.3, 1.0, 2, gb, pa, NULL, da, dr, NULL, 0) == WA_INVALID_ARGUMENT &&
            isnan(pa[0]) && isnan(pa[1]),
         "NULL P_retract, P_approach NaN");
   CHECK(wa_gap_law(WA_MODEL_DW, 0.3, 1.0, 2, NULL, pa, pr, da, dr, NULL, 0) == WA_INVALID_ARGUMENT,
         "NULL gbar");
   st = wa_gap_law_msg(WA_MODEL_MD, 0.3, NAN, 2, gb, pa, pr, da, dr, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "mu") && isnan(pr[1]), "mu NaN: '%s'", msg);
   CHECK(wa_gap_law(5, 0.3, 1.0, 2, gb, pa, pr, da, dr, NULL, 0) == WA_INVALID_ARGUMENT, "model 5");
}

/* Regression (issue item 5a): wa_gap_law_msg returned WA_OK with a stale message ("gap_path:
   no equilibrium near the branch at a point of the quadrature") where the library retried a
   failed inner solve successfully; the fuzzer found it (3 in 2.2e6 calls). On WA_OK the
   message is "", and the values are those of the plain wa_gap_law and, at gbar* = 0, the
   full-contact load of wa_gap_path's cycle. */
static void test_gap_law_message_on_ok(void) {
   const double alpha = 1.4489361929536397, mu = 21754883.931522951;
   double gb[3] = {0.0, 0.5, 1.2}, pa[3], pr[3], da[3], dr[3], pa2[3], pr2[3], da2[3], dr2[3];
   double a[64], c[64], p[64], g[64], w, wf, gt;
   int stage[64], ev[64], zc[64], n = 0, k, st, st2;
   char msg[256];
   memset(msg, 'x', sizeof msg);
   st = wa_gap_law_msg(WA_MODEL_DW, alpha, mu, 3, gb, pa, pr, da, dr, msg, sizeof msg);
   CHECK(st == WA_OK && msg[0] == '\0', "gap law at DW (%.17g, %.17g): st %d message '%.80s'",
         alpha, mu, st, msg);
   memset(msg, 'x', sizeof msg);
   st = wa_gap_law_msg(WA_MODEL_DW, alpha, mu, 0, NULL, NULL, NULL, NULL, NULL, msg, sizeof msg);
   CHECK(st == WA_OK && msg[0] == '\0', "gap law n = 0: st %d message '%.80s'", st, msg);
   st2 = wa_gap_law(WA_MODEL_DW, alpha, mu, 3, gb, pa2, pr2, da2, dr2, NULL, 0);
   CHECK(st2 == WA_OK && !memcmp(pa, pa2, sizeof pa) && !memcmp(pr, pr2, sizeof pr) &&
            !memcmp(da, da2, sizeof da) && !memcmp(dr, dr2, sizeof dr),
         "gap law: _msg and plain differ (st %d)", st2);
   st = wa_gap_path(WA_MODEL_DW, alpha, mu, 64, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0);
   for (k = 0; k < n && ev[k] != WA_GAP_EVENT_FULL_CONTACT_REACHED; k++) continue;
   CHECK(st == WA_OK && k < n && g[k] == 0.0 && pa[0] == p[k] && pr[0] == p[k],
         "gap law at gbar* 0: %.17g %.17g, full contact reached at P* %.17g", pa[0], pr[0],
         k < n ? p[k] : NAN);
}

static void test_gap_critical(void) {
   double v[WA_GAP_CRITICAL_COUNT], a[16], c[16], p[16], g[16], w, wf, gt, fc, pf, gb[1],
      pa[1], pr[1], da[1], dr[1];
   int stage[16], ev[16], zc[16], n, k, m, st;
   static const double mus[3] = {0.3, 1.0, 5.0};
   char msg[256];
   st = wa_gap_critical(WA_MODEL_WESTERGAARD, 0.3, 1.0, v, NULL, 0);
   CHECK(st == WA_OK && v[WA_GAP_CRITICAL_G_TOUCH] == 1.0 && v[WA_GAP_CRITICAL_P_JUMP_IN] == 0 &&
            v[WA_GAP_CRITICAL_G_CONTACT] == 1.0 && v[WA_GAP_CRITICAL_G_CONTACT_LOST] == 1.0 &&
            v[WA_GAP_CRITICAL_G_INTERACTION_LOST] == 1.0 && v[WA_GAP_CRITICAL_P_MIN] == 0.0,
         "westergaard: no jump, contact made and lost at gbar* = 1, P_min = 0");
   st = wa_gap_critical(WA_MODEL_JKR, 0.3, 1.0, v, NULL, 0);
   CHECK(st == WA_OK && isinf(v[WA_GAP_CRITICAL_P_MIN]) && v[WA_GAP_CRITICAL_P_MIN] < 0 &&
            v[WA_GAP_CRITICAL_G_P_MIN] == 0.0 && v[WA_GAP_CRITICAL_P_JUMP_IN] < 0,
         "jkr: P_min = -inf at gbar* = 0, a jump-in");
   for (m = 2; m < 4; m++)
      for (k = 0; k < 3; k++) {
         int i, last_loss = -1;
         st = wa_gap_critical(models[m], 0.3, mus[k], v, NULL, 0);
         wa_gap_path(models[m], 0.3, mus[k], 16, stage, ev, zc, a, c, p, g, &n, &w, &wf, &gt, NULL, 0);
         wa_critical_forces(models[m], 0.3, mus[k], &fc, &pf, NULL, 0);
         CHECK(st == WA_OK && v[WA_GAP_CRITICAL_G_TOUCH] == gt &&
                  v[WA_GAP_CRITICAL_G_INTERACTION_LOST] == g[n - 1],
               "model %d mu %g: g_touch and interaction lost are the path's", models[m], mus[k]);
         CHECK(close_to(v[WA_GAP_CRITICAL_P_MIN], pf, 1e-12),
               "model %d mu %g: P_min %.17g = P_pf %.17g", models[m], mus[k],
               v[WA_GAP_CRITICAL_P_MIN], pf);
         for (i = 0; i < n; i++) {
            if (stage[i] == WA_STAGE_RETRACTION)
               CHECK(p[i] >= v[WA_GAP_CRITICAL_P_MIN], "P_min below every retraction event");
            if (ev[i] == WA_GAP_EVENT_CONTACT_LOST ||
                (ev[i] == WA_GAP_EVENT_JUMP_START && a[i] > 0 && a[i + 1] == 0))
               if (stage[i] == WA_STAGE_RETRACTION) last_loss = i;
         }
         CHECK(last_loss >= 0 && v[WA_GAP_CRITICAL_G_CONTACT_LOST] == g[last_loss] &&
                  v[WA_GAP_CRITICAL_P_CONTACT_LOST] == p[last_loss],
               "model %d mu %g: contact lost is the path's event", models[m], mus[k]);
         if (ev[1] == WA_GAP_EVENT_JUMP_START)
            CHECK(v[WA_GAP_CRITICAL_P_JUMP_IN] == p[2] && v[WA_GAP_CRITICAL_A_JUMP_IN] == a[2],
                  "jump-in lands on the path's event");
         /* the gap law on retraction at gbar*(P_min) is P_min */
         gb[0] = v[WA_GAP_CRITICAL_G_P_MIN];
         st = wa_gap_law(models[m], 0.3, mus[k], 1, gb, pa, pr, da, dr, NULL, 0);
         CHECK(st == WA_OK && close_to(pr[0], v[WA_GAP_CRITICAL_P_MIN], 1e-8),
               "model %d mu %g: gap law at gbar*(P_min) %.17g vs %.17g", models[m], mus[k],
               pr[0], v[WA_GAP_CRITICAL_P_MIN]);
      }
   for (k = 0; k < WA_GAP_CRITICAL_COUNT; k++) v[k] = 1;
   CHECK(wa_gap_critical(WA_MODEL_DW, -1.0, 1.0, v, NULL, 0) == WA_INVALID_ARGUMENT && isnan(v[0]) &&
            isnan(v[WA_GAP_CRITICAL_COUNT - 1]),
         "alpha < 0: NaN values");
   CHECK(wa_gap_critical(WA_MODEL_DW, 0.3, 1.0, NULL, NULL, 0) == WA_INVALID_ARGUMENT, "NULL values");
   CHECK(wa_gap_critical(-1, 0.3, 1.0, v, NULL, 0) == WA_INVALID_ARGUMENT && isnan(v[3]), "model -1");
   st = wa_gap_critical_msg(WA_MODEL_MD, 0.3, INFINITY, v, msg, sizeof msg);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "mu") && isnan(v[4]), "mu inf: '%s'", msg);
   st = wa_gap_critical_msg(WA_MODEL_MD, 0.3, 1.0, v, msg, sizeof msg);
   CHECK(st == WA_OK && msg[0] == '\0', "empty message on success");
}

/* ------------------------------------------------- 0.2 compatibility names */

/* Same bits (NaN included) in n doubles / ints; same text. */
static int same_d(const double *x, const double *y, int n) {
   return n <= 0 || memcmp(x, y, (size_t)n * sizeof *x) == 0;
}
static int same_i(const int *x, const int *y, int n) {
   return n <= 0 || memcmp(x, y, (size_t)n * sizeof *x) == 0;
}

/* Every 0.2 name (removed in 0.4) is its 0.3 function with the 0.2 arguments, bit for bit:
   statuses, every output (the failure values too) and messages, on valid calls, invalid
   ones and too small capacities. The _gap names require gbar (the 0.3 functions take
   NULL); wa_critical_sweep_status requires row_status; wa_adhesion_map_control is
   wa_adhesion_map with n_mu = 60. */
static void test_compat_forwards(void) {
   enum { CAP = 400 };
   static const struct { int model; double alpha, mu, a; } pt[] = {
      {WA_MODEL_DW, 0.3, 1.0, 0.2}, {WA_MODEL_MD, 0.3, 1.0, 0.3}, {WA_MODEL_JKR, 0.3, 1.0, 0.5},
      {WA_MODEL_DW, 0.3, 1.0, 0.0}, {WA_MODEL_DW, -1.0, 1.0, 0.2}, {7, 0.3, 1.0, 0.2}};
   static double a1[CAP], c1[CAP], p1[CAP], g1[CAP], a2[CAP], c2[CAP], p2[CAP], g2[CAP];
   static int z1[CAP], s1[CAP], e1[CAP], z2[CAP], s2[CAP], e2[CAP];
   char m1[256], m2[256];
   int k, j, st1, st2, n1, n2, caps[3] = {CAP, 1, 0};
   for (k = 0; k < (int)(sizeof pt / sizeof pt[0]); k++) {
      int md = pt[k].model;
      double al = pt[k].alpha, mu = pt[k].mu, a = pt[k].a, x[5] = {-0.5, -0.1, 0.0, 0.2, 3.3};
      /* wa_equilibrium: _msg (no gbar), _gap and _gap_msg (gbar) */
      st1 = wa_equilibrium(md, al, mu, a, c1, p1, z1, NULL, m1, sizeof m1);
      st2 = wa_equilibrium_msg(md, al, mu, a, c2, p2, z2, m2, sizeof m2);
      CHECK(st1 == st2 && same_d(c1, c2, 1) && same_d(p1, p2, 1) && same_i(z1, z2, 1) &&
               !strcmp(m1, m2), "point %d: wa_equilibrium_msg differs (%d %d)", k, st1, st2);
      st1 = wa_equilibrium(md, al, mu, a, c1, p1, z1, g1, m1, sizeof m1);
      st2 = wa_equilibrium_gap_msg(md, al, mu, a, c2, p2, z2, g2, m2, sizeof m2);
      CHECK(st1 == st2 && same_d(c1, c2, 1) && same_d(p1, p2, 1) && same_i(z1, z2, 1) &&
               same_d(g1, g2, 1) && !strcmp(m1, m2),
            "point %d: wa_equilibrium_gap_msg differs (%d %d)", k, st1, st2);
      st2 = wa_equilibrium_gap(md, al, mu, a, c2, p2, z2, g2);
      CHECK(st1 == st2 && same_d(c1, c2, 1) && same_d(p1, p2, 1) && same_d(g1, g2, 1),
            "point %d: wa_equilibrium_gap differs (%d %d)", k, st1, st2);
      CHECK(wa_equilibrium_gap(md, al, mu, a, c2, p2, z2, NULL) == WA_INVALID_ARGUMENT,
            "point %d: wa_equilibrium_gap requires gbar", k);
      /* wa_roots: full, too small and count-only capacities */
      for (j = 0; j < 3; j++) {
         int cap = caps[j], w;
         n1 = n2 = -1;
         st1 = wa_roots(md, al, mu, a, cap, c1, p1, z1, NULL, &n1, m1, sizeof m1);
         st2 = wa_roots_msg(md, al, mu, a, cap, c2, p2, z2, &n2, m2, sizeof m2);
         w = n1 < cap ? n1 : cap;
         CHECK(st1 == st2 && n1 == n2 && same_d(c1, c2, w) && same_d(p1, p2, w) &&
                  same_i(z1, z2, w) && !strcmp(m1, m2),
               "point %d cap %d: wa_roots_msg differs (%d %d)", k, cap, st1, st2);
         st1 = wa_roots(md, al, mu, a, cap, c1, p1, z1, g1, &n1, m1, sizeof m1);
         st2 = wa_roots_gap_msg(md, al, mu, a, cap, c2, p2, z2, g2, &n2, m2, sizeof m2);
         w = n1 < cap ? n1 : cap;
         CHECK(st1 == st2 && n1 == n2 && same_d(c1, c2, w) && same_d(g1, g2, w) &&
                  !strcmp(m1, m2),
               "point %d cap %d: wa_roots_gap_msg differs (%d %d)", k, cap, st1, st2);
         st2 = wa_roots_gap(md, al, mu, a, cap, c2, p2, z2, g2, &n2);
         CHECK(st1 == st2 && n1 == n2 && same_d(p1, p2, w) && same_d(g1, g2, w),
               "point %d cap %d: wa_roots_gap differs (%d %d)", k, cap, st1, st2);
      }
      CHECK(wa_roots_gap(md, al, mu, a, 4, c2, p2, z2, NULL, &n2) == WA_INVALID_ARGUMENT,
            "point %d: wa_roots_gap requires gbar", k);
      /* wa_profile */
      st1 = wa_equilibrium(md, al, mu, a, c1, p1, z1, NULL, NULL, 0);
      st1 = wa_profile(md, al, mu, a, st1 == WA_OK ? c1[0] : 0.3, 5, x, p1, g1, m1, sizeof m1);
      st2 = wa_profile_msg(md, al, mu, a, st1 == WA_OK ? c1[0] : 0.3, 5, x, p2, g2, m2,
                           sizeof m2);
      CHECK(st1 == st2 && same_d(p1, p2, 5) && same_d(g1, g2, 5) && !strcmp(m1, m2),
            "point %d: wa_profile_msg differs (%d %d)", k, st1, st2);
   }
   for (k = 0; k < 3; k++) {
      int md = k == 2 ? WA_MODEL_MD : WA_MODEL_DW;
      double al = k == 1 ? NAN : 0.3, mu = 5.0, f1[2], f2[2], w1[3], w2[3];
      double mus[3] = {0.1, 1.0, 5.0}, v1[WA_GAP_CRITICAL_COUNT], v2[WA_GAP_CRITICAL_COUNT];
      double q1[6], q2[6];
      int r1[3], r2[3], w;
      /* wa_trace_branch: _msg, _gap, _gap_msg; a too small capacity */
      for (j = 0; j < 2; j++) {
         int cap = j == 0 ? CAP : 10;
         st1 = wa_trace_branch(md, al, mu, cap, a1, c1, p1, z1, s1, e1, NULL, &n1, m1, sizeof m1);
         st2 = wa_trace_branch_msg(md, al, mu, cap, a2, c2, p2, z2, s2, e2, &n2, m2, sizeof m2);
         w = n1 < cap ? n1 : cap;
         CHECK(st1 == st2 && n1 == n2 && same_d(a1, a2, w) && same_d(c1, c2, w) &&
                  same_d(p1, p2, w) && same_i(z1, z2, w) && same_i(s1, s2, w) &&
                  same_i(e1, e2, w) && !strcmp(m1, m2),
               "case %d cap %d: wa_trace_branch_msg differs (%d %d)", k, cap, st1, st2);
         st1 = wa_trace_branch(md, al, mu, cap, a1, c1, p1, z1, s1, e1, g1, &n1, m1, sizeof m1);
         st2 = wa_trace_branch_gap_msg(md, al, mu, cap, a2, c2, p2, z2, s2, e2, g2, &n2, m2,
                                       sizeof m2);
         CHECK(st1 == st2 && n1 == n2 && same_d(a1, a2, w) && same_d(g1, g2, w) &&
                  !strcmp(m1, m2),
               "case %d cap %d: wa_trace_branch_gap_msg differs (%d %d)", k, cap, st1, st2);
         st2 = wa_trace_branch_gap(md, al, mu, cap, a2, c2, p2, z2, s2, e2, g2, &n2);
         CHECK(st1 == st2 && n1 == n2 && same_d(p1, p2, w) && same_d(g1, g2, w),
               "case %d cap %d: wa_trace_branch_gap differs (%d %d)", k, cap, st1, st2);
      }
      CHECK(wa_trace_branch_gap(md, 0.3, mu, 4, a2, c2, p2, z2, s2, e2, NULL, &n2) ==
               WA_INVALID_ARGUMENT, "case %d: wa_trace_branch_gap requires gbar", k);
      /* critical forces, load path, sweep (row_status NULL / required) */
      st1 = wa_critical_forces(md, al, mu, &f1[0], &f1[1], m1, sizeof m1);
      st2 = wa_critical_forces_msg(md, al, mu, &f2[0], &f2[1], m2, sizeof m2);
      CHECK(st1 == st2 && same_d(f1, f2, 2) && !strcmp(m1, m2),
            "case %d: wa_critical_forces_msg differs (%d %d)", k, st1, st2);
      for (j = 0; j < 2; j++) {
         int cap = j == 0 ? 64 : 2;
         st1 = wa_load_path(md, al, mu, cap, z1, e1, a1, c1, p1, &n1, &f1[0], &f1[1], m1,
                            sizeof m1);
         st2 = wa_load_path_msg(md, al, mu, cap, z2, e2, a2, c2, p2, &n2, &f2[0], &f2[1], m2,
                                sizeof m2);
         w = n1 < cap ? n1 : cap;
         CHECK(st1 == st2 && n1 == n2 && same_i(z1, z2, w) && same_i(e1, e2, w) &&
                  same_d(a1, a2, w) && same_d(p1, p2, w) && same_d(f1, f2, 2) &&
                  !strcmp(m1, m2),
               "case %d cap %d: wa_load_path_msg differs (%d %d)", k, cap, st1, st2);
      }
      if (k == 1) mus[1] = -1.0;                 /* an invalid mu as well */
      st1 = wa_critical_sweep(md, 0.3, 3, mus, c1, p1, z1, s1, NULL, m1, sizeof m1);
      st2 = wa_critical_sweep_msg(md, 0.3, 3, mus, c2, p2, z2, s2, m2, sizeof m2);
      CHECK(st1 == st2 && same_d(c1, c2, 3) && same_d(p1, p2, 3) && same_i(z1, z2, 3) &&
               same_i(s1, s2, 3) && !strcmp(m1, m2),
            "case %d: wa_critical_sweep_msg differs (%d %d)", k, st1, st2);
      st1 = wa_critical_sweep(md, 0.3, 3, mus, c1, p1, z1, s1, r1, m1, sizeof m1);
      st2 = wa_critical_sweep_status(md, 0.3, 3, mus, c2, p2, z2, s2, r2, m2, sizeof m2);
      CHECK(st1 == st2 && same_d(c1, c2, 3) && same_i(s1, s2, 3) && same_i(r1, r2, 3) &&
               !strcmp(m1, m2),
            "case %d: wa_critical_sweep_status differs (%d %d)", k, st1, st2);
      CHECK(wa_critical_sweep_status(md, 0.3, 3, mus, c2, p2, z2, s2, NULL, NULL, 0) ==
               WA_INVALID_ARGUMENT, "case %d: wa_critical_sweep_status requires row_status", k);
      /* gap control */
      for (j = 0; j < 2; j++) {
         int cap = j == 0 ? 64 : 3;
         st1 = wa_gap_path(md, al, 1.0, cap, z1, e1, s1, a1, c1, p1, g1, &n1, &w1[0], &w1[1],
                           &w1[2], m1, sizeof m1);
         st2 = wa_gap_path_msg(md, al, 1.0, cap, z2, e2, s2, a2, c2, p2, g2, &n2, &w2[0],
                               &w2[1], &w2[2], m2, sizeof m2);
         w = n1 < cap ? n1 : cap;
         CHECK(st1 == st2 && n1 == n2 && same_i(z1, z2, w) && same_i(e1, e2, w) &&
                  same_i(s1, s2, w) && same_d(a1, a2, w) && same_d(c1, c2, w) &&
                  same_d(p1, p2, w) && same_d(g1, g2, w) && same_d(w1, w2, 3) &&
                  !strcmp(m1, m2),
               "case %d cap %d: wa_gap_path_msg differs (%d %d)", k, cap, st1, st2);
      }
      for (j = 0; j < 6; j++) a1[j] = 0.25 * j - (k == 1 ? 0.5 : 0.0);
      st1 = wa_gap_law(md, 0.3, 1.0, 6, a1, c1, p1, g1, q1, m1, sizeof m1);
      st2 = wa_gap_law_msg(md, 0.3, 1.0, 6, a1, c2, p2, g2, q2, m2, sizeof m2);
      CHECK(st1 == st2 && same_d(c1, c2, 6) && same_d(p1, p2, 6) && same_d(g1, g2, 6) &&
               same_d(q1, q2, 6) && !strcmp(m1, m2),
            "case %d: wa_gap_law_msg differs (%d %d)", k, st1, st2);
      st1 = wa_gap_critical(md, al, 1.0, v1, m1, sizeof m1);
      st2 = wa_gap_critical_msg(md, al, 1.0, v2, m2, sizeof m2);
      CHECK(st1 == st2 && same_d(v1, v2, WA_GAP_CRITICAL_COUNT) && !strcmp(m1, m2),
            "case %d: wa_gap_critical_msg differs (%d %d)", k, st1, st2);
   }
   /* the map: wa_adhesion_map_control is wa_adhesion_map at n_mu = 60, both controls */
   for (k = 0; k < 3; k++) {
      const double alpha[2] = {0.3, 0.31};
      int control = k == 2 ? 4 : k + 1, w;
      st1 = wa_adhesion_map(WA_MODEL_DW, control, 2, alpha, 1e-2, 1e2, 60, CAP, z1, a1, c1, &n1,
                            m1, sizeof m1);
      st2 = wa_adhesion_map_control(WA_MODEL_DW, control, 2, alpha, 1e-2, 1e2, CAP, z2, a2, c2,
                                    &n2);
      w = n1 < CAP ? n1 : CAP;
      CHECK(st1 == st2 && n1 == n2 && same_i(z1, z2, w) && same_d(a1, a2, w) &&
               same_d(c1, c2, w) && (st1 == WA_OK) == (m1[0] == 0),
            "control %d: wa_adhesion_map_control differs (%d %d, %d %d points, '%s')", control,
            st1, st2, n1, n2, m1);
   }
}

/* P_fc_peak of the cycle at N against an independent reading of wa_lj_trace at the same
   N: under load control the load on reaching trace point k is M_k, the running maximum
   of P* over points 0..k (a jump at a fold keeps the load until the curve comes back to
   it), so the load at which b* first reaches 1/2, between points j - 1 and j (j the
   first point with b* >= 1/2), lies in [M_{j-1}, M_j]. */
static void lj_peak_against_trace(double peak, int n) {
   enum { cap = 4000 };
   static double ps[cap], gb[cap], as[cap], bs[cap];
   double m_prev = -INFINITY, m = -INFINITY;
   int st, n_pts = 0, j;
   char msg[256];
   st = wa_lj_trace(0.3, 3.0, n, 0, NULL, cap, ps, gb, as, bs, NULL, NULL, NULL, &n_pts, NULL,
                    msg, 256);
   CHECK(st == WA_OK && n_pts > 10, "lj_trace at N = %d: %d '%s'", n, st, msg);
   if (st != WA_OK) return;
   for (j = 0; j < n_pts && bs[j] < 0.5; j++) {
      m_prev = m;
      m = fmax(m, ps[j]);
   }
   CHECK(j > 0 && j < n_pts, "lj_trace: b* reaches 1/2 at point %d of %d", j, n_pts);
   if (j == 0 || j >= n_pts) return;
   m_prev = m;
   m = fmax(m, ps[j]);
   CHECK(peak >= m_prev - 1e-12 && peak <= m + 1e-12,
         "lj P_fc_peak %.12g outside [%.12g, %.12g] (trace point %d, b* %.6g)", peak, m_prev,
         m, j, bs[j]);
}

/* Smooth adhesion: the cycle against the converged reference values (within the
   returned N vs N/2 estimates), NULL optional outputs give the same values, the trace's
   counts, capacity and options, and the documented failures. */
static void test_lj(void) {
   double fc, pf, snap, w, peak, err[5], fc2, pf2, snap2, w2, peak2, sin_prof[32];
   int st, n_used = -1, i, n_pts = -1, n_pts2 = -1, n_used_t = -1;
   char msg[256];
   enum { cap = 4000 };
   static double ps[cap], gb[cap], as[cap], bs[cap], ps2[cap], gb2[cap], as2[cap], bs2[cap];
   static int sl[cap], sg[cap], ev[cap];
   strcpy(msg, "x");
   st = wa_lj_cycle(0.3, 3.0, 0, 0, NULL, &fc, &pf, &snap, &w, &peak, err, &n_used, msg, 256);
   CHECK(st == WA_OK && msg[0] == '\0', "lj_cycle status %d message '%s'", st, msg);
   CHECK(fabs(fc - 0.99600001838) <= err[0] + 1e-9, "lj P_fc %.12g err %g", fc, err[0]);
   CHECK(fabs(pf + 0.40595099926) <= err[1] + 1e-9, "lj P_pf %.12g err %g", pf, err[1]);
   CHECK(n_used >= 16 && n_used % 4 == 0, "lj n_used %d", n_used);
   CHECK(w > 0 && isfinite(snap) && err[2] >= 0 && err[3] >= 0, "lj W* %g snap %g", w, snap);
   /* P_fc_peak: the value of Python's critical_forces("lj", 0.3, 3.0).P_fc_peak and of
      `critical --model lj` (the same N); here the snap load, within 0.2 % of DW's P_fc */
   CHECK(fabs(peak - 0.3864226987) <= 1e-9 && err[4] >= 0 && err[4] < 1e-4,
         "lj P_fc_peak %.12g err %g", peak, err[4]);
   st = wa_lj_cycle(0.3, 3.0, 0, 0, NULL, &fc2, &pf2, &snap2, &w2, NULL, NULL, NULL, NULL, 0);
   CHECK(st == WA_OK && fc2 == fc && pf2 == pf && snap2 == snap && w2 == w,
         "lj_cycle with NULL optionals differs");
   st = wa_lj_cycle(0.3, 3.0, 0, 0, NULL, &fc2, &pf2, &snap2, &w2, &peak2, NULL, NULL, NULL, 0);
   CHECK(st == WA_OK && peak2 == peak, "lj_cycle P_fc_peak without errors differs");
   lj_peak_against_trace(peak, n_used);

   /* failures: each names its argument; the outputs are NaN, n_used 0 */
   peak = 0.0;
   st = wa_lj_cycle(0.3, 3.0, 250, 0, NULL, &fc, &pf, &snap, &w, &peak, err, &n_used, msg,
                    256);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "n = 250") && isnan(fc) && isnan(peak) &&
            isnan(err[3]) && isnan(err[4]) && n_used == 0, "lj_cycle n = 250: %d '%s'", st,
         msg);
   st = wa_lj_cycle(0.3, 3.0, 8, 0, NULL, &fc, &pf, &snap, &w, NULL, NULL, NULL, msg, 256);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "n = 8"), "lj_cycle n = 8: '%s'", msg);
   for (i = 0; i < 32; i++) sin_prof[i] = 1.0 - cos(2.0 * pi * i / 32.0);
   st = wa_lj_cycle(0.3, 3.0, 0, 3, sin_prof, &fc, &pf, &snap, &w, NULL, NULL, NULL, msg, 256);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "n_profile = 3"), "lj n_profile: '%s'", msg);
   st = wa_lj_cycle(0.3, 0.0, 0, 0, NULL, &fc, &pf, &snap, &w, NULL, NULL, NULL, msg, 256);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "mu"), "lj mu = 0: '%s'", msg);
   st = wa_lj_cycle(NAN, 3.0, 0, 0, NULL, &fc, &pf, &snap, &w, NULL, NULL, NULL, msg, 256);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "alpha"), "lj alpha NaN: '%s'", msg);
   st = wa_lj_cycle(0.3, 3.0, 0, 0, NULL, &fc, NULL, &snap, &w, &peak, NULL, NULL, msg, 256);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "P_pf") && isnan(fc) && isnan(peak),
         "lj NULL: '%s'", msg);
   {  /* a sample that is not finite: refused (it crashed the solver before the check) */
      double bad_prof[4] = {0.0, INFINITY, 2.0, 1.0};
      st = wa_lj_cycle(0.3, 3.0, 16, 4, bad_prof, &fc, &pf, &snap, &w, NULL, NULL, NULL, msg, 256);
      CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "profile") && isnan(fc),
            "lj non-finite profile: status %d '%s'", st, msg);
      bad_prof[1] = NAN;
      st = wa_lj_trace(0.3, 3.0, 16, 4, bad_prof, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL,
                       &n_pts, NULL, msg, 256);
      CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "profile"),
            "lj_trace NaN profile: status %d '%s'", st, msg);
   }
   st = wa_lj_cycle(0.3, 3.0, 20000, 0, NULL, &fc, &pf, &snap, &w, NULL, NULL, NULL, msg, 256);
   CHECK(st == WA_INVALID_ARGUMENT && isnan(fc), "lj n = 20000: %d '%s'", st, msg);

   /* the trace at n = 256, the sinusoid given as samples = NULL, counts and capacity */
   st = wa_lj_trace(0.3, 3.0, 256, 0, NULL, cap, ps, gb, as, bs, sl, sg, ev, &n_pts,
                    &n_used_t, msg, 256);
   CHECK(st == WA_OK && msg[0] == '\0' && n_pts > 10 && n_used_t == 256,
         "lj_trace %d n %d N %d '%s'", st, n_pts, n_used_t, msg);
   if (st != WA_OK) return;
   CHECK(ev[0] == 8 && ev[n_pts - 1] == 8 && sl[n_pts - 1] == 1 && sg[n_pts - 1] == 1 &&
            fabs(as[n_pts - 1] - 0.5) < 1e-12 && as[0] >= 0 && gb[0] > gb[n_pts - 1],
         "lj_trace ends");
   for (i = 1, st = 0; i < n_pts - 1; i++) st += ev[i] == 1;
   CHECK(st >= 2, "lj_trace has %d folds of P*", st);
   st = wa_lj_trace(0.3, 3.0, 256, 32, sin_prof, cap, ps2, gb2, as2, bs2, NULL, NULL, NULL,
                    &n_pts2, NULL, msg, 256);
   /* the samples of the sinusoid give the same far-apart start (the interpolant is exact) */
   CHECK(st == WA_OK && n_pts2 > 10 && fabs(ps2[0] - ps[0]) < 1e-9 &&
            fabs(gb2[0] - gb[0]) < 1e-9 * gb[0] && fabs(as2[n_pts2 - 1] - 0.5) < 1e-12,
         "lj_trace with sampled sinusoid %d: %d points", st, n_pts2);
   st = wa_lj_trace(0.3, 3.0, 256, 0, NULL, 5, ps2, gb2, as2, bs2, NULL, NULL, NULL, &n_pts2,
                    NULL, msg, 256);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n_pts2 == n_pts && same_d(ps2, ps, 5) &&
            same_d(bs2, bs, 5) && strstr(msg, "capacity = 5"),
         "lj_trace capacity 5: %d %d '%s'", st, n_pts2, msg);
   st = wa_lj_trace(0.3, 3.0, 256, 0, NULL, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL,
                    &n_pts2, NULL, msg, 256);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n_pts2 == n_pts, "lj_trace count query %d", st);
   st = wa_lj_trace(0.3, 3.0, 255, 0, NULL, cap, ps2, gb2, as2, bs2, NULL, NULL, NULL,
                    &n_pts2, &n_used_t, msg, 256);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "n") && n_pts2 == 0 && n_used_t == 0,
         "lj_trace n odd: '%s'", msg);
   st = wa_lj_trace(0.3, 3.0, 256, 0, NULL, cap, ps2, NULL, as2, bs2, NULL, NULL, NULL,
                    &n_pts2, NULL, msg, 256);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "gbar"), "lj_trace NULL gbar: '%s'", msg);
   st = wa_lj_trace(0.3, 3.0, 256, 0, NULL, cap, ps2, gb2, as2, bs2, NULL, NULL, NULL, NULL,
                    NULL, msg, 256);
   CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, "n_points"), "lj_trace NULL n_points");
}

/* wa_lj_profile against an independent reading of wa_lj_trace: the state drawn is the
   load-stable traced point with a* nearest the target (the rule, recomputed here from the
   trace), the fields reproduce the state (mean traction = P*, mean gap = gbar*, the
   fraction of nodes with h <= eps = 2 a* within a node), x* = i/N - 1/2; capacity, NULL
   optional outputs and every refused argument. */
static void test_lj_profile(void) {
   enum { cap = 4000, np = 256 };
   static double ps[cap], gb[cap], as[cap], bs[cap];
   static int sl[cap];
   double x[np], t[np], h[np], x2[np], t2[np], h2[np], state[4], state2[4];
   const double targets[5] = {0.0, 0.1, 0.2, 0.37, 0.5};
   const double eps = cbrt(4.0 * pow(0.3, 4)) / 3.0; /* eps/Delta at alpha 0.3, mu 3 */
   int st, n_pts = -1, n_trace = -1, i, k, best, inside, ok;
   double miss, mean_t, mean_h;
   char msg[256];
   st = wa_lj_trace(0.3, 3.0, np, 0, NULL, cap, ps, gb, as, bs, sl, NULL, NULL, &n_trace,
                    NULL, msg, 256);
   CHECK(st == WA_OK, "lj_profile: the reference trace %d '%s'", st, msg);
   if (st != WA_OK) return;
   for (k = 0; k < 5; k++) {
      strcpy(msg, "x");
      st = wa_lj_profile(0.3, 3.0, np, 0, NULL, targets[k], np, x, t, h, state, &n_pts, msg,
                         256);
      CHECK(st == WA_OK && n_pts == np && msg[0] == '\0', "lj_profile a* %g: %d %d '%s'",
            targets[k], st, n_pts, msg);
      if (st != WA_OK) continue;
      for (i = 0, best = -1, miss = INFINITY; i < n_trace; i++) /* the rule, by hand */
         if (sl[i] && fabs(as[i] - targets[k]) < miss) miss = fabs(as[i] - targets[k]), best = i;
      CHECK(best >= 0 && state[0] == as[best] && state[1] == bs[best] && state[2] == ps[best] &&
               state[3] == gb[best],
            "lj_profile a* %g: state (%g %g %g %g) is not trace point %d", targets[k],
            state[0], state[1], state[2], state[3], best);
      for (i = 0, mean_t = 0, mean_h = 0, inside = 0, ok = 1; i < np; i++) {
         mean_t += t[i] / np;
         mean_h += h[i] / np;
         inside += h[i] <= eps;
         ok = ok && isfinite(t[i]) && h[i] >= 0 && fabs(x[i] - ((double)i / np - 0.5)) < 1e-15;
      }
      CHECK(ok && fabs(mean_t - state[2]) < 1e-9 && fabs(mean_h - state[3]) < 1e-12 &&
               fabs(inside / (2.0 * np) - state[0]) <= 1.0 / np,
            "lj_profile a* %g: fields vs state: P* %g mean %g, gbar %g mean %g, a* %g nodes %g",
            targets[k], state[2], mean_t, state[3], mean_h, state[0], inside / (2.0 * np));
   }
   CHECK(state[0] == 0.5, "lj_profile a* 1/2 draws full contact: a* %g", state[0]);
   /* NULL state: the same fields; capacity 5: the first 5 points, N and the state */
   st = wa_lj_profile(0.3, 3.0, np, 0, NULL, 0.5, np, x2, t2, h2, NULL, &n_pts, NULL, 0);
   CHECK(st == WA_OK && same_d(x2, x, np) && same_d(t2, t, np) && same_d(h2, h, np),
         "lj_profile with NULL state differs: %d", st);
   for (i = 0; i < np; i++) x2[i] = t2[i] = h2[i] = -7;
   st = wa_lj_profile(0.3, 3.0, np, 0, NULL, 0.5, 5, x2, t2, h2, state2, &n_pts, msg, 256);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n_pts == np && same_d(x2, x, 5) && same_d(t2, t, 5) &&
            same_d(h2, h, 5) && x2[5] == -7 && same_d(state2, state, 4) &&
            strstr(msg, "capacity = 5"),
         "lj_profile capacity 5: %d %d '%s'", st, n_pts, msg);
   st = wa_lj_profile(0.3, 3.0, np, 0, NULL, 0.5, 0, NULL, NULL, NULL, NULL, &n_pts, msg, 256);
   CHECK(st == WA_CAPACITY_TOO_SMALL && n_pts == np, "lj_profile count query %d %d", st, n_pts);

   /* the smallest subnormal a* is valid: the state of a* = 0 */
   st = wa_lj_profile(0.3, 3.0, np, 0, NULL, 0.0, np, x, t, h, state, &n_pts, NULL, 0);
   st += 10 * wa_lj_profile(0.3, 3.0, np, 0, NULL, 5e-324, np, x2, t2, h2, state2, &n_pts,
                            NULL, 0);
   CHECK(st == WA_OK && same_d(state, state2, 4) && same_d(h, h2, np),
         "lj_profile a* = 5e-324 is not the state of a* = 0: %d", st);
   /* refused: the status, the argument named, *n_points 0, state NaN, arrays untouched */
   {
      const struct { double alpha, mu, a; int n, n_prof, capacity, null_x, null_np;
                     const char *name; } bad[] = {
         {0.3, 3.0, NAN, np, 0, np, 0, 0, "a_star"},
         {0.3, 3.0, -0.1, np, 0, np, 0, 0, "a_star"},
         {0.3, 3.0, 0.7, np, 0, np, 0, 0, "a_star"},
         {0.3, 3.0, INFINITY, np, 0, np, 0, 0, "a_star"},
         {0.3, 3.0, 1e300, np, 0, np, 0, 0, "a_star"},
         {0.3, 3.0, -5e-324, np, 0, np, 0, 0, "a_star"},
         {NAN, 3.0, 0.2, np, 0, np, 0, 0, "alpha"},
         {1e300, 3.0, 0.2, np, 0, np, 0, 0, "alpha"},
         {5e-324, 3.0, 0.2, np, 0, np, 0, 0, "alpha"},
         {0.3, 0.0, 0.2, np, 0, np, 0, 0, "mu"},
         {0.3, INFINITY, 0.2, np, 0, np, 0, 0, "mu"},
         {0.3, 5e-324, 0.2, np, 0, np, 0, 0, "mu"},
         {0.3, 3.0, 0.2, 255, 0, np, 0, 0, "n"},
         {0.3, 3.0, 0.2, 6, 0, np, 0, 0, "n"},
         {0.3, 3.0, 0.2, -8, 0, np, 0, 0, "n"},
         {0.3, 3.0, 0.2, 1 << 30, 0, np, 0, 0, "n"},
         {0.3, 3.0, 0.2, np, 3, np, 0, 0, "n_profile"},
         {0.3, 3.0, 0.2, np, 4, np, 0, 0, "profile"},
         {0.3, 3.0, 0.2, np, 0, -1, 0, 0, "capacity"},
         {0.3, 3.0, 0.2, np, 0, np, 1, 0, "x_star"},
         {0.3, 3.0, 0.2, np, 0, np, 0, 1, "n_points"}};
      const double nan_prof[4] = {0.0, NAN, 2.0, 1.0};
      for (k = 0; k < (int)(sizeof bad / sizeof bad[0]); k++) {
         for (i = 0; i < np; i++) x2[i] = -7;
         n_pts = -1;
         state2[0] = 1;
         st = wa_lj_profile(bad[k].alpha, bad[k].mu, bad[k].n, bad[k].n_prof,
                            bad[k].n_prof == 4 ? nan_prof : (bad[k].n_prof ? x : NULL), bad[k].a,
                            bad[k].capacity, bad[k].null_x ? NULL : x2, t2, h2, state2,
                            bad[k].null_np ? NULL : &n_pts, msg, 256);
         CHECK(st == WA_INVALID_ARGUMENT && strstr(msg, bad[k].name) && isnan(state2[0]) &&
                  (bad[k].null_np || n_pts == 0) && x2[0] == -7,
               "lj_profile bad case %d (%s): status %d n %d '%s'", k, bad[k].name, st, n_pts,
               msg);
      }
   }
   /* the message buffer: capacity 0 and NULL copy nothing, 1 only the NUL */
   strcpy(msg, "untouched");
   st = wa_lj_profile(0.3, 3.0, np, 0, NULL, NAN, np, x2, t2, h2, NULL, &n_pts, msg, 0);
   CHECK(st == WA_INVALID_ARGUMENT && strcmp(msg, "untouched") == 0, "message_capacity 0");
   st = wa_lj_profile(0.3, 3.0, np, 0, NULL, NAN, np, x2, t2, h2, NULL, &n_pts, msg, 1);
   CHECK(st == WA_INVALID_ARGUMENT && msg[0] == '\0', "message_capacity 1: '%s'", msg);
   st = wa_lj_profile(0.3, 3.0, np, 0, NULL, NAN, np, x2, t2, h2, NULL, &n_pts, NULL, 256);
   CHECK(st == WA_INVALID_ARGUMENT, "NULL message");
}

int main(void) {
   test_version();
   test_closed_forms();
   test_status_messages();
   test_equilibrium_closed_forms();
   test_equilibrium_cohesive();
   test_equilibrium_invalid();
   test_messages();
   test_roots_closed_forms();
   test_roots_invalid();
   test_roots_grid();
   test_roots_capacity();
   test_threads();
   test_branch_every_model();
   test_branch_dw_values();
   test_branch_capacity();
   test_branch_invalid();
   test_critical_values();
   test_critical_invalid();
   test_load_path();
   test_critical_sweep();
   test_sweep_keeps_rows();
   test_branch_threads();
   test_adhesion_map();
   test_adhesion_map_control();
   test_gap_functions();
   test_profile();
   test_gap_path();
   test_gap_law();
   test_gap_law_message_on_ok();
   test_gap_critical();
   test_compat_forwards();
   test_lj();
   test_lj_profile();
   printf("%d passed, %d failed\n", n_pass, n_fail);
   return n_fail == 0 ? 0 : 1;
}
