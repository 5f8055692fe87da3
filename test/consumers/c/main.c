/* Host-code check (C, pkg-config): the DW equilibrium at alpha = 0.3, mu = 1, a* = 0.2
 * against the mpmath reference row of test/data/dw.txt. */
#include <math.h>
#include <stdio.h>

#include "wavyadhesion.h"

int main(void) {
   const double c_ref = 0.32795133117893904447, p_ref = 0.17439576801132992591;
   double c, p;
   char msg[256];
   int zone, st = wa_equilibrium(WA_MODEL_DW, 0.3, 1.0, 0.2, &c, &p, &zone, NULL, msg, sizeof msg);
   if (st != WA_OK) {
      fprintf(stderr, "wa_equilibrium: %s: %s\n", wa_status_message(st), msg);
      return 1;
   }
   printf("wavyadhesion %s: c* = %.16f  P* = %.16f\n", wa_version(), c, p);
   if (fabs(c - c_ref) > 1e-12 * c_ref || fabs(p - p_ref) > 1e-12 * p_ref) {
      fprintf(stderr, "c* or P* differs from the reference\n");
      return 1;
   }
   return 0;
}
