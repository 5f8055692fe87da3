/* C-interface test: `fpm test capi`. Calls every function of include/wavyadhesion.h for
 * every model, with valid and invalid arguments, NULL pointers and too small capacities.
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
   st = wa_equilibrium(WA_MODEL_WESTERGAARD, 0.3, 1.0, 0.25, &c, &p, &z);
   CHECK(st == WA_OK && c == 0.25 && close_to(p, 0.5, 1e-15) && z == WA_ZONE_INSIDE,
         "westergaard at 1/4: st %d c %g P %g z %d", st, c, p, z);
   st = wa_equilibrium(WA_MODEL_WESTERGAARD, 0.3, 1.0, 0.5, &c, &p, &z);
   CHECK(st == WA_OK && c == 0.5 && p == 1.0 && z == WA_ZONE_FULL_CONTACT,
         "westergaard at 1/2: st %d c %g P %g z %d", st, c, p, z);
   st = wa_equilibrium(WA_MODEL_JKR, 0.3, 1.0, 0.2, &c, &p, &z);
   CHECK(st == WA_OK && c == 0.2 && p == wa_jkr_load(0.3, 0.2) && z == WA_ZONE_INSIDE,
         "jkr at 0.2: st %d c %g P %g z %d", st, c, p, z);
   st = wa_equilibrium(WA_MODEL_JKR, 0.3, 1.0, 0.5, &c, &p, &z);
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
      st = wa_equilibrium(m, 0.3, 1e-12, 0.2, &c, &p, &z);
      CHECK(st == WA_OK && close_to(p, wa_westergaard_load(0.2), 1e-9),
            "model %d, mu -> 0: st %d P %.17g", m, st, p);
      st = wa_equilibrium(m, 0.3, 0.0, 0.2, &c, &p, &z);
      CHECK(st == WA_OK && close_to(p, wa_westergaard_load(0.2), 1e-14),
            "model %d, mu = 0: st %d P %.17g", m, st, p);
      st = wa_equilibrium(m, 0.3, 1.0, 0.5, &c, &p, &z);
      CHECK(st == WA_OK && c == 0.5 && z == WA_ZONE_FULL_CONTACT,
            "model %d at 1/2: st %d c %g z %d", m, st, c, z);
      for (i = 1; i < 10; i++) {
         double a = 0.05 * i, cr[8], pr[8];
         int zr[8], n = -1;
         st = wa_equilibrium(m, 0.3, 1.0, a, &c, &p, &z);
         CHECK(st == WA_OK && c >= a && c <= 0.5 && isfinite(p) &&
                  (z == WA_ZONE_INSIDE || z == WA_ZONE_WHOLE_PERIOD),
               "model %d at a* %g: st %d c %g P %g z %d", m, a, st, c, p, z);
         st = wa_roots(m, 0.3, 1.0, a, 8, cr, pr, zr, &n);
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
         int st = wa_equilibrium(models[m], bad_alpha[i], 1.0, 0.2, &c, &p, &z);
         CHECK(st == WA_INVALID_ARGUMENT && isnan(c) && isnan(p) && z == 0,
               "model %d alpha %g: st %d", models[m], bad_alpha[i], st);
      }
      for (i = 0; i < 3; i++)
         CHECK(wa_equilibrium(models[m], 0.3, bad_mu[i], 0.2, &c, &p, &z) ==
                  WA_INVALID_ARGUMENT,
               "model %d mu %g", models[m], bad_mu[i]);
      for (i = 0; i < 4; i++)
         CHECK(wa_equilibrium(models[m], 0.3, 1.0, bad_a[i], &c, &p, &z) ==
                  WA_INVALID_ARGUMENT,
               "model %d a* %g", models[m], bad_a[i]);
      CHECK(wa_equilibrium(models[m], 0.3, 1.0, 0.2, NULL, &p, &z) == WA_INVALID_ARGUMENT,
            "NULL c_star");
      CHECK(wa_equilibrium(models[m], 0.3, 1.0, 0.2, &c, NULL, &z) == WA_INVALID_ARGUMENT,
            "NULL P_star");
      CHECK(wa_equilibrium(models[m], 0.3, 1.0, 0.2, &c, &p, NULL) == WA_INVALID_ARGUMENT,
            "NULL zone_case");
   }
   CHECK(wa_equilibrium(4, 0.3, 1.0, 0.2, &c, &p, &z) == WA_INVALID_ARGUMENT, "model 4");
   CHECK(wa_equilibrium(-1, 0.3, 1.0, 0.2, &c, &p, &z) == WA_INVALID_ARGUMENT, "model -1");
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
      st = wa_roots(m, 0.3, 1.0, 0.2, 2, c, p, z, &n);
      CHECK(st == WA_OK && n == 1 && c[0] == 0.2 && z[0] == WA_ZONE_INSIDE && c[1] == -1,
            "model %d roots: st %d n %d", m, st, n);
      CHECK(p[0] == (m == WA_MODEL_JKR ? wa_jkr_load(0.3, 0.2) : wa_westergaard_load(0.2)),
            "model %d root load", m);
      st = wa_roots(m, 0.3, 1.0, 0.2, 0, NULL, NULL, NULL, &n);
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
      CHECK(wa_roots(md, 0.3, 1.0, 0.9, 4, c, p, z, &n) == WA_INVALID_ARGUMENT && n == 0,
            "model %d a* 0.9", md);
      CHECK(wa_roots(md, NAN, 1.0, 0.2, 4, c, p, z, &n) == WA_INVALID_ARGUMENT && n == 0,
            "model %d alpha NaN", md);
      CHECK(wa_roots(md, 0.3, -1.0, 0.2, 4, c, p, z, &n) == WA_INVALID_ARGUMENT, "mu < 0");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, -3, c, p, z, &n) == WA_INVALID_ARGUMENT,
            "capacity < 0");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, 4, c, p, z, NULL) == WA_INVALID_ARGUMENT,
            "NULL n_roots");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, 4, NULL, p, z, &n) == WA_INVALID_ARGUMENT,
            "NULL c_star");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, 4, c, NULL, z, &n) == WA_INVALID_ARGUMENT,
            "NULL P_star");
      CHECK(wa_roots(md, 0.3, 1.0, 0.2, 4, c, p, NULL, &n) == WA_INVALID_ARGUMENT,
            "NULL zone_case");
   }
   CHECK(wa_roots(17, 0.3, 1.0, 0.2, 4, c, p, z, &n) == WA_INVALID_ARGUMENT && n == 0,
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
               int st = wa_roots(m, alphas[ia], mus[im], a, 8, c, p, z, &n);
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
   int st = wa_roots(WA_MODEL_MD, 0.3, 1.0, 0.3, 3, c, p, z, &n);
   CHECK(st == WA_OK && n == 3 && z[0] == 1 && z[1] == 1 && z[2] == 2 && c[0] < c[1],
         "md at (0.3, 1, 0.3): st %d n %d (want 3 states: 1, 1, 2)", st, n);
   if (st != WA_OK || n < 2) return;
   for (cap = 0; cap < n; cap++) {
      double c1[4] = {-7, -7, -7, -7}, p1[4] = {-7, -7, -7, -7};
      int z1[4] = {-7, -7, -7, -7}, n1 = 0;
      st = wa_roots(WA_MODEL_MD, 0.3, 1.0, 0.3, cap, c1, p1, z1, &n1);
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
      st = wa_roots(k, 0.3, 1.0, 0.2, 0, c0, NULL, NULL, &n0);
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
                                  &job->z[i]);
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

int main(void) {
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
   printf("%d passed, %d failed\n", n_pass, n_fail);
   return n_fail == 0 ? 0 : 1;
}
