!> display: none
!>
!> The two elliptic integrals of the double-Westergaard model, (2.25b) and (2.28c) of
!> the paper (doc/theory.md, "Double-Westergaard"), in closed form, and a quadrature of the first for cross-checks.
!>
!>    I*(A,C) = int_A^C sqrt(1-X^2) sqrt(C^2-X^2) sqrt(X^2-A^2) dX,   0 < A <= C <= 1
!>    I_A*(A) = int_A^1 (1-X^2) sqrt(X^2-A^2) dX = I*(A,1)
!>
!> With X^2 = C^2 - (C^2-A^2) sin^2(phi), s = sin(phi), k = cos(phi):
!>
!>    W = I*/(C^2-A^2)^2 = int_0^(pi/2) s^2 k^2 sqrt(a1 k^2 + b1 s^2)/sqrt(a2 k^2 + b2 s^2) dphi  (E1)
!>
!> with a1 = 1-C^2, b1 = 1-A^2, a2 = C^2, b2 = A^2. W is O(1) and, being a positive
!> integral, has relative condition number at most 1/2 in each of a1, b1, a2, b2: it is
!> computed from C^2-A^2 and 1-C^2 that the caller forms without cancellation.
!>
!> Closed form. With tan^2(phi) = y u, y = a1/b1, x = a2/b2 and kc^2 = y/x,
!>
!>    W = sqrt(b1)/(2A) (y^2/sqrt(x)) int_0^oo u(1+u)/((1+yu)^3 sqrt(u(1+u)(1+kc^2 u))) du,
!>
!> and u(1+u) = u(1+yu) + (1-y)u^2 turns the triple pole into two derivatives, with
!> positive weights, of Bulirsch's general complete elliptic integral
!>
!>    cel(kc,p,1,0) = int_0^(pi/2) k^2/((k^2 + p s^2) sqrt(k^2 + kc^2 s^2)) dphi
!>                  = (1/2) int_0^oo du/((1+pu) sqrt(u(1+u)(1+kc^2 u))),
!>
!>    W = (sqrt(b1)/C) [-y c1 + (1-y) c2],  cel(kc, y(1+t), 1, 0) = c0 + c1 t + c2 t^2 + ...  (E2)
!>
!> (c1 < 0 < c2). cel_pole_series gets c0, c1, c2 in double precision from Bartky's
!> quadratically convergent transformation (Bulirsch 1969), arranged so that no step
!> cancels (see there). For C = 1 (and 1-C^2 < 1e-20 (1-A^2)) and for I_A*:
!>
!>    W(A,1) = I_A*(A)/(1-A^2)^2                                                        (E3)
!>    8 I_A* = s(2 + A^2) - A^2 (4 - A^2) atanh(s),   s = sqrt(1-A^2)                   (E4)
!>    I_A*   = (2/15) z^(5/2) 2F1(1/2, 2; 7/2; z),     z = 1-A^2                         (E5)
!>
!> The equivalent form in Carlson's integrals, derived and checked in study/verify/check_istar.py,
!>    W = sqrt(b1)/(2A) [2 al R_F(0,x,y) + (2/3) be R_D(0,y,x) + (2/3) ga R_J(0,x,y,1)],
!>    al = (xy-2x+1)/(8(x-1)(y-1)),  be = -x(x-y)(xy-2x+2y-1)/(8(x-1)^2(y-1)),
!>    ga = (x^2y^2-4xy^2+6xy-4x+1)/(8(x-1)^2(y-1)),
!> is not the default: its three terms cancel by factors 8 to 2e4 over the domain and like
!> 1/(x-1)^2 as C -> A, and R_F, R_D, R_J diverge together as C -> 1 or A -> 0. It is kept
!> as istar_carlson (GSL's R_F, R_D, R_J) for the cross-check test and the work-precision
!> study (doc/accuracy-performance.md).
module wa_elliptic
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_invalid_argument, wa_not_converged, wa_numerical_error
   use wa_gsl, only: gsl_sf_result, gsl_sf_ellint_rf_e, gsl_sf_ellint_rd_e, gsl_sf_ellint_rj_e, &
      gsl_set_error_handler_off, gsl_prec_double, gsl_success
   use, intrinsic :: iso_c_binding, only: c_funptr
   implicit none
   private

   public :: istar_scaled, ia_star, istar_quadrature, istar_carlson

   !> Relative AGM gap at which Bartky's iteration stops; the last step squares it.
   real(wp), parameter :: agm_gap = 1.0e-9_wp
   !> Bound on the iteration count (13 suffice for kc = 1e-150).
   integer, parameter :: max_bartky = 40
   !> Smallest A accepted by istar_scaled (keeps kc far from underflow).
   real(wp), parameter :: a_min = 1.0e-150_wp
   !> Below a_min, W(A,C) = W(0,C) to double precision where C >= c_min_a0.
   real(wp), parameter :: c_min_a0 = 1.0e-100_wp
   !> Below this y = (1-C^2)/(1-A^2), W(A,C) = W(A,1) (1 + O(y)): use I_A* (E3).
   real(wp), parameter :: y_at_one = 1.0e-20_wp

   !> Extended precision for I_A*, whose closed form cancels like 3/(1-A^2)^2 as A -> 1:
   !> 64-bit mantissa on x86 (quad elsewhere), double where neither exists.
   integer, parameter :: xp = merge(selected_real_kind(18), wp, selected_real_kind(18) > 0)
   !> Below this 1-A^2 the series (E5) is summed; above it the closed form (E4) in `xp`
   !> loses at most 530 ulp of `xp` (< 0.3 ulp of double). Without an extended kind the
   !> series runs up to 0.9, where (E4) cancels by 2.1 at most.
   real(wp), parameter :: ia_series_max = merge(0.1_wp, 0.9_wp, precision(1.0_xp) >= 18)

contains

   !> W = I*(A,C)/(C^2-A^2)^2, (2.25b) of the paper (doc/theory.md) scaled to O(1), from accurate
   !> inputs: a = A >= 1e-150, c = C in [A, 1], d2 = C^2-A^2 >= 0, omc2 = 1-C^2 >= 0 (may be
   !> 0), d2 + omc2 = 1-A^2 > 0. At d2 = 0 it returns the limit pi sqrt(1-A^2)/(16A).
   !> For 0 <= A < 1e-150 it returns W(0,C) (istar_scaled_a0), which needs C >= 1e-100.
   !> Relative error below 1.5e-15 (measured against mpmath, study/verify/check_istar.py), about
   !> 100 ns per call. NaN for invalid input.
   elemental function istar_scaled(a, c, d2, omc2) result(w)
      !> A = sin(pi a*)
      real(wp), intent(in) :: a
      !> C = sin(pi c*)
      real(wp), intent(in) :: c
      !> C^2 - A^2, formed without cancellation
      real(wp), intent(in) :: d2
      !> 1 - C^2, formed without cancellation
      real(wp), intent(in) :: omc2
      real(wp) :: w
      real(wp) :: b1, y, cel(0:2)
      if (a < a_min .and. a >= 0.0_wp .and. c >= c_min_a0 .and. c <= 1.0_wp &
            .and. omc2 >= 0.0_wp .and. omc2 <= 1.0_wp) then
         w = istar_scaled_a0(c, omc2)      ! dropping A changes W by O((A/C)^2 ln(C/A))
         return
      end if
      if (.not. (a >= a_min .and. c >= a .and. c <= 1.0_wp .and. d2 >= 0.0_wp &
            .and. omc2 >= 0.0_wp .and. d2 + omc2 > 0.0_wp .and. d2 + omc2 <= 1.5_wp)) then
         w = ieee_value(w, ieee_quiet_nan)
         return
      end if
      b1 = d2 + omc2
      y = omc2/b1
      if (y < y_at_one) then
         w = ia_star(a, min(b1, 1.0_wp))/b1**2                               ! (E3)
      else
         cel = cel_pole_series(sqrt(y)*(a/c), y)
         w = sqrt(b1)/c*(-y*cel(1) + (d2/b1)*cel(2))                         ! (E2)
      end if
   end function istar_scaled

   !> W(0,C) = I*(0,C)/C^4, the a* -> 0 limit of istar_scaled (c = C, omc2 = 1 - C^2):
   !>   8 I*(0,C) = (1 + C^2) C - (1 - C^2)^2 artanh(C)                               (E6)
   !> (int_0^C X sqrt(1-X^2) sqrt(C^2-X^2) dX with u = C^2 - X^2), and for C < 1/2, where
   !> (E6) cancels, its series I*(0,C)/C^3 = sum t_k C^(2k), t_0 = 1/3,
   !> t_(k+1) = t_k (2k-1)/(2k+5).
   pure function istar_scaled_a0(c, omc2) result(w)
      real(wp), intent(in) :: c, omc2
      real(wp) :: w
      real(wp) :: term, total, c2
      integer :: k
      if (c < 0.5_wp) then
         c2 = c*c
         term = 1.0_wp/3.0_wp
         total = term
         do k = 0, 60
            term = term*c2*real(2*k - 1, wp)/real(2*k + 5, wp)
            total = total + term
            if (abs(term) <= 0.5_wp*epsilon(1.0_wp)*total) exit
         end do
         w = total/c
      else if (omc2 > 0.0_wp) then
         w = ((2.0_wp - omc2)*c - omc2**2*0.5_wp*log((1.0_wp + c)**2/omc2))/(8.0_wp*c**4)
      else
         w = 0.25_wp
      end if
   end function istar_scaled_a0

   !> I_A*(A) = int_A^1 (1-X^2) sqrt(X^2-A^2) dX, (2.28c) of the paper (doc/theory.md), in closed
   !> form from a = A in [0,1] and oma2 = 1-A^2 given accurately. It vanishes like
   !> (2/15)(1-A^2)^(5/2) as A -> 1 and tends to 1/4 as A -> 0. Where A^2 >= 1/2 only oma2
   !> is used, elsewhere only a. NaN for invalid input.
   elemental function ia_star(a, oma2) result(ia)
      !> A = sin(pi a*)
      real(wp), intent(in) :: a
      !> 1 - A^2, formed without cancellation
      real(wp), intent(in) :: oma2
      real(wp) :: ia
      real(xp) :: z, s, a2
      if (.not. (a >= 0.0_wp .and. a <= 1.0_wp .and. oma2 >= 0.0_wp &
            .and. oma2 <= 1.0_wp)) then
         ia = ieee_value(ia, ieee_quiet_nan)
         return
      end if
      z = oma2
      if (oma2 < ia_series_max) then
         ia = real(ia_series(z), wp)                                         ! (E5)
      else if (oma2 <= 0.5_wp) then
         s = sqrt(z)                           ! 1 - z is exact in xp for z >= 2^-10
         ia = real(ia_closed(s, 1.0_xp - z, atanh(s)), wp)                   ! (E4)
      else if (a > 0.0_wp) then
         a2 = real(a, xp)**2
         s = sqrt(1.0_xp - a2)
         ia = real(ia_closed(s, a2, log((1.0_xp + s)/a)), wp)                ! (E4)
      else
         ia = 0.25_wp
      end if
   end function ia_star

   !> W = I*(A,C)/(C^2-A^2)^2 by tanh-sinh quadrature of (E1), for cross-checks and
   !> work-precision comparisons; C^2-A^2 and 1-C^2 are formed as (C-A)(C+A), (1-C)(1+C).
   !> The step is halved until two estimates agree to rtol (at least 3 halvings).
   pure subroutine istar_quadrature(a, c, w, status, rtol, neval)
      !> A, 0 < A < C
      real(wp), intent(in) :: a
      !> C, A < C <= 1
      real(wp), intent(in) :: c
      !> the estimate of W (NaN if the arguments are invalid)
      real(wp), intent(out) :: w
      !> wa_ok, wa_invalid_argument, or wa_not_converged (w is then the last estimate)
      integer, intent(out) :: status
      !> relative agreement of successive estimates asked for, default 1e-15
      real(wp), intent(in), optional :: rtol
      !> number of integrand evaluations used
      integer, intent(out), optional :: neval
      real(wp) :: coef(4), tol
      integer :: n
      if (present(neval)) neval = 0
      if (.not. (a > 0.0_wp .and. c > a .and. c <= 1.0_wp)) then
         w = ieee_value(w, ieee_quiet_nan)
         status = wa_invalid_argument
         return
      end if
      tol = 1.0e-15_wp
      if (present(rtol)) tol = max(rtol, 1.0e-16_wp)
      coef = [(1.0_wp - c)*(1.0_wp + c), (1.0_wp - a)*(1.0_wp + a), c**2, a**2]
      call tanh_sinh(coef, tol, w, n, status)
      if (present(neval)) neval = n
   end subroutine istar_quadrature

   ! ---------------------------------------------------------------- internals

   !> Taylor coefficients in t of cel(kc, p(1+t), 1, 0), by Bulirsch's algorithm for p > 0
   !> (Bulirsch 1969; `cel` in Numerical Recipes, 2nd ed., 6.11) reorganised for the pole.
   !> With Q = p, e = qc = kc, em = 1 and a = 1, b = 0 at the start, the step is
   !>    rho = (Q-e)/(Q+e),  Q' = (Q+e)^2/Q,  a' = 2a - D,  D' = rho D  (D = a - b/sqrt(Q)),
   !>    em' = em + qc,  qc' = 2 sqrt(e),  e' = qc' em'   (the AGM of 1 and kc),
   !> and after N steps cel = (pi/2)(2^N/em) C_0, where C_0 = 1 - R_0 and
   !>    R_m = 1/2 + (rho_m/2) R_(m+1),   R_N = sqrt(Q_N)/(em + sqrt(Q_N)).
   !> Only rho depends on t, through q = ln Q = ln p + ln(1+t) (coefficients al, be). The
   !> backward recurrence keeps both R_m and C_m with terms of one sign (C for rho >= 0 as
   !> sigma + (rho/2) C', R for rho < 0 as (1-sigma) - (rho/2) C', sigma = e/(Q+e)), and
   !> takes the t-coefficients from the R form, whose two terms do not cancel. The sum
   !> of 2^-(k+1) D_k in the forward direction would cancel by a factor ~ln(1/kc).
   pure function cel_pole_series(kc, p) result(cel)
      real(wp), intent(in) :: kc, p
      real(wp) :: cel(0:2)
      real(wp) :: rho(0:2, max_bartky), sig(2, max_bartky)
      real(wp) :: q, q_inv, q_next, al, be, e, em, em_old, qc, inv, drho, r(0:2), c0
      integer :: n, m
      q = p; q_inv = 1.0_wp/p; al = 1.0_wp; be = -0.5_wp
      qc = kc; e = kc; em = 1.0_wp
      do n = 1, max_bartky
         inv = 1.0_wp/(q + e)
         sig(:, n) = [e*inv, q*inv]                      ! sigma, 1 - sigma
         rho(0, n) = (q - e)*inv
         drho = 2.0_wp*sig(1, n)*sig(2, n)              ! d rho/d q
         rho(1:2, n) = [drho*al, drho*(be - 0.5_wp*rho(0, n)*al**2)]
         be = rho(0, n)*be + 0.5_wp*drho*al**2
         al = rho(0, n)*al
         q_next = (q + e)**2*q_inv                       ! Q' = (Q+e)^2/Q, no division
         q_inv = q*inv**2
         q = q_next
         em_old = em
         em = em + qc
         if (abs(em_old - qc) <= agm_gap*em_old) exit
         qc = 2.0_wp*sqrt(e)
         e = qc*em
      end do
      n = min(n, max_bartky)
      r = logistic_series(sqrt(q)/(em + sqrt(q)), al, be)
      c0 = em/(em + sqrt(q))
      do m = n, 1, -1
         call fold_back(rho(:, m), sig(:, m), r, c0)
      end do
      cel = scale(0.5_wp*pi/em, n)*[c0, -r(1), -r(2)]            ! (pi/2) 2^n/em
   end function cel_pole_series

   !> One backward step R_m = 1/2 + (rho/2) R_(m+1) on (R, C = 1 - R), see cel_pole_series.
   pure subroutine fold_back(rho, sig, r, c0)
      real(wp), intent(in) :: rho(0:2), sig(2)
      real(wp), intent(inout) :: r(0:2), c0
      real(wp) :: r0
      r(2) = 0.5_wp*(rho(2)*r(0) + rho(1)*r(1) + rho(0)*r(2))
      r(1) = 0.5_wp*(rho(1)*r(0) + rho(0)*r(1))
      r0 = r(0)
      if (rho(0) >= 0.0_wp) then
         r(0) = 0.5_wp + 0.5_wp*rho(0)*r0
         c0 = sig(1) + 0.5_wp*rho(0)*c0
      else
         r(0) = sig(2) - 0.5_wp*rho(0)*c0
         c0 = 0.5_wp - 0.5_wp*rho(0)*r0
      end if
   end subroutine fold_back

   !> Taylor coefficients in t of h(q(t)), h = 1/(1 + em exp(-q/2)), from h and the
   !> coefficients al, be of q: h' = h(1-h)/2, h'' = h'(1-2h)/2.
   pure function logistic_series(h, al, be) result(ht)
      real(wp), intent(in) :: h, al, be
      real(wp) :: ht(0:2)
      real(wp) :: dh
      dh = 0.5_wp*h*(1.0_wp - h)
      ht = [h, dh*al, dh*(be + 0.25_wp*(1.0_wp - 2.0_wp*h)*al**2)]
   end function logistic_series

   !> (E4): 8 I_A* = s(2 + A^2) - A^2 (4 - A^2) atanh(s), s = sqrt(1-A^2), from the
   !> antiderivatives of sqrt(X^2-A^2) and X^2 sqrt(X^2-A^2).
   pure function ia_closed(s, a2, atanh_s) result(ia)
      real(xp), intent(in) :: s, a2, atanh_s
      real(xp) :: ia
      ia = 0.125_xp*(s*(2.0_xp + a2) - a2*(4.0_xp - a2)*atanh_s)
   end function ia_closed

   !> (E5): I_A* = (2/15) z^(5/2) 2F1(1/2, 2; 7/2; z), z = 1-A^2, from X^2 = A^2 + z w in
   !> (2.28c) and the binomial series of 1/sqrt(1 - z(1-w)): positive terms.
   pure function ia_series(z) result(ia)
      real(xp), intent(in) :: z
      real(xp) :: ia
      real(xp) :: term, total
      integer :: n
      term = 1.0_xp
      total = 1.0_xp
      do n = 0, 500
         term = term*z*((n + 0.5_xp)*(n + 2))/((n + 1)*(n + 3.5_xp))
         total = total + term
         if (term <= epsilon(term)*total) exit
      end do
      ia = (2.0_xp/15.0_xp)*z**2*sqrt(z)*total
   end function ia_series

   !> Tanh-sinh rule for (E1) on [0, pi/2]: nodes |t| <= 4, step halved from 1/2 until
   !> two estimates agree to tol (at least 3 halvings, at most 12).
   pure subroutine tanh_sinh(coef, tol, w, neval, status)
      real(wp), intent(in) :: coef(4), tol
      real(wp), intent(out) :: w
      integer, intent(out) :: neval, status
      real(wp), parameter :: t_max = 4.0_wp
      integer, parameter :: max_level = 12
      real(wp) :: h, total, previous
      integer :: level, j
      h = 0.5_wp
      total = ts_node(coef, 0.0_wp)
      do j = 1, nint(t_max/h)
         total = total + ts_node(coef, j*h) + ts_node(coef, -j*h)
      end do
      neval = 2*nint(t_max/h) + 1
      w = total*h
      status = wa_not_converged
      do level = 1, max_level
         previous = w
         h = 0.5_wp*h
         do j = 1, nint(t_max/h), 2                      ! only the new, odd nodes
            total = total + ts_node(coef, j*h) + ts_node(coef, -j*h)
         end do
         neval = neval + nint(t_max/h) + 1
         w = total*h
         if (level >= 3 .and. abs(w - previous) <= tol*abs(w)) then
            status = wa_ok
            return
         end if
      end do
   end subroutine tanh_sinh

   !> Weight times integrand of (E1) at the tanh-sinh node t: phi = (pi/4)(1 + tanh(u)),
   !> u = (pi/2) sinh(t), with phi and pi/2 - phi formed without cancellation.
   pure function ts_node(coef, t) result(f)
      real(wp), intent(in) :: coef(4), t
      real(wp) :: f
      real(wp) :: u, ex, near, far, s, k
      u = 0.5_wp*pi*sinh(t)
      ex = exp(-2.0_wp*abs(u))
      near = 0.5_wp*pi*ex/(1.0_wp + ex)      ! (pi/4)(1 - tanh|u|): distance to the near end
      far = 0.5_wp*pi/(1.0_wp + ex)          ! (pi/4)(1 + tanh|u|)
      if (u > 0.0_wp) then
         s = sin(far); k = sin(near)         ! phi near pi/2
      else
         s = sin(near); k = sin(far)         ! phi near 0
      end if
      f = (s*k)**2*sqrt(coef(1)*k**2 + coef(2)*s**2)/sqrt(coef(3)*k**2 + coef(4)*s**2)
      ! d phi/dt = (pi/4)(pi/2) cosh(t)/cosh(u)^2, 1/cosh(u)^2 = 4 ex/(1+ex)^2
      f = f*(0.125_wp*pi**2)*cosh(t)*4.0_wp*ex/(1.0_wp + ex)**2
   end function ts_node

   !> W = I*/(C^2-A^2)^2 from the Carlson form above with GSL's R_F, R_D, R_J (0 < A,
   !> C < 1, C > A). Loses digits to cancellation (see the module header); GSL failures
   !> are mapped to wa_numerical_error.
   subroutine istar_carlson(a, c, d2, omc2, w, status)
      real(wp), intent(in) :: a, c, d2, omc2
      real(wp), intent(out) :: w
      integer, intent(out) :: status
      type(gsl_sf_result) :: rf, rd, rj
      type(c_funptr) :: previous
      real(wp) :: b1, x, y, xm1, ym1, al, be, ga
      integer :: s1, s2, s3

      w = ieee_value(w, ieee_quiet_nan)
      status = wa_invalid_argument
      if (.not. (a > 0.0_wp .and. c < 1.0_wp .and. d2 > 0.0_wp .and. omc2 > 0.0_wp)) return
      previous = gsl_set_error_handler_off()
      b1 = (1.0_wp - a)*(1.0_wp + a)
      x = (c/a)**2
      y = omc2/b1
      xm1 = d2/a**2
      ym1 = -d2/b1
      al = (x*y - 2*x + 1)/(8*xm1*ym1)
      be = -x*(x - y)*(x*y - 2*x + 2*y - 1)/(8*xm1**2*ym1)
      ga = (x**2*y**2 - 4*x*y**2 + 6*x*y - 4*x + 1)/(8*xm1**2*ym1)
      s1 = gsl_sf_ellint_rf_e(0.0_wp, x, y, gsl_prec_double, rf)
      s2 = gsl_sf_ellint_rd_e(0.0_wp, y, x, gsl_prec_double, rd)
      s3 = gsl_sf_ellint_rj_e(0.0_wp, x, y, 1.0_wp, gsl_prec_double, rj)
      if (any([s1, s2, s3] /= gsl_success)) then
         status = wa_numerical_error
         return
      end if
      w = sqrt(b1)/(2*a)*(2*al*rf%val + (2.0_wp/3)*be*rd%val + (2.0_wp/3)*ga*rj%val)
      status = wa_ok
   end subroutine istar_carlson

end module wa_elliptic
