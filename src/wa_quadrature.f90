!> display: none
!>
!> The alternative quadratures that the options of dw_equilibrium and md_equilibrium
!> select in place of the library's closed form (DW's W = I*/(C^2-A^2)^2) and fixed graded
!> Gauss rules (MD's Psi_c): what the work-precision study (doc/accuracy-performance.md)
!> measures the defaults against. None is used unless an option asks for it. Also the
!> library's one literal 16-point Gauss-Legendre rule on [0, 1] (gl16_x, gl16_w), which
!> the mean gap and the MD gap of src/wa_separation.f90 sum their panels with, and the
!> n-point Gauss-Legendre rules on [-1, 1] with their polynomial interpolants (gl_rule,
!> gl_interpolate, gl_value_slope, gl_invert) that the panels along a chain
!> (src/wa_chain_cover.f90) hold P* and gbar* in.
!>
!> DW, W by (E1) of src/wa_elliptic.f90:
!>   wa_quad_istar_carlson  the Carlson form with GSL's R_F, R_D, R_J (istar_carlson)
!>   wa_quad_istar_qag      GSL QAG (Gauss-Kronrod 21) of (E1) on the accurate coefficients
!> MD, K = int_0^1 artanh(r) r G(r) dr, G = 1/((1 - k^2 r^2) sqrt(1 - sin^2 s r^2)),
!> Psi_c = -(2/pi) A q sin^2 s K (src/wa_md_psi.f90):
!>   psi_gauss_rules, k_gauss  singularity subtraction only: an N-node Gauss rule for the
!>                             weight -ln(1-r) plus N-node Gauss-Legendre for ln(1+r)
!>   wa_quad_psi_k             GSL QAWS (weight ln(1-r)) + QAG for the ln(1+r) part, or GSL
!>                             QAG or QAGS of the whole log-singular integrand, epsrel tol
!>
!> The GSL ones are bind(C) and reached through the pure interfaces quad_istar_carlson,
!> quad_istar_qag and quad_psi_k of wa_gsl: from the caller's side each is a pure function
!> of its value arguments. Each allocates and frees its own workspace and switches GSL's
!> abort-on-error handler off (as wa_elliptic does; GSL's handler is process-wide, so it is
!> never restored: "off" set by any number of threads at once stays "off"). Where GSL
!> reports a failure (tolerance not reached, roundoff detected) the result is NaN, which
!> the solvers report as wa_numerical_error: an unconverged quadrature is never returned as
!> a converged value (the study counts such points as failures of the method).
module wa_quadrature
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_ptr, c_size_t, c_funptr, &
      c_funloc, c_loc, c_f_pointer
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok
   use wa_elliptic, only: istar_carlson
   use wa_gsl, only: gsl_function, gsl_set_error_handler_off, &
      gsl_integration_workspace_alloc, gsl_integration_workspace_free, &
      gsl_integration_qaws_table_alloc, gsl_integration_qaws_table_free, &
      gsl_integration_qaws, gsl_integration_qag, gsl_integration_qags
   implicit none
   private

   public :: wa_quad_istar_carlson, wa_quad_istar_qag, wa_quad_psi_k
   public :: psi_gauss_rules, k_gauss, psi_k_gsl, sort2
   public :: quad_psi_qaws, quad_psi_qag, quad_psi_qags
   public :: gl16_x, gl16_w
   public :: gl_rule_type, gl_rule, gl_interpolate, gl_value_slope, gl_invert

   !> Gauss-Legendre, 16 points on [0, 1] (the panels of src/wa_separation.f90). Literal
   !> constants, not gauss_legendre01(16): nodes computed in double at run time would not
   !> be bit-identical to these.
   real(wp), parameter :: gl16_x(16) = [ &
      0.005299532504175033701923_wp, 0.02771248846338371196101_wp, &
      0.06718439880608412805977_wp, 0.1222977958224984867434_wp, &
      0.1910618777986781147139_wp, 0.2709916111713863151807_wp, &
      0.3591982246103705422868_wp, 0.4524937450811812866824_wp, &
      0.5475062549188187133176_wp, 0.6408017753896294577132_wp, &
      0.7290083888286136848193_wp, 0.8089381222013218852861_wp, &
      0.8777022041775015132566_wp, 0.9328156011939158719402_wp, &
      0.972287511536616288039_wp, 0.9947004674958249662981_wp]
   real(wp), parameter :: gl16_w(16) = [ &
      0.01357622970587704742589_wp, 0.03112676196932394643142_wp, &
      0.04757925584124639240497_wp, 0.06231448562776693602624_wp, &
      0.07479799440828836604818_wp, 0.08457825969750126909095_wp, &
      0.09130170752246179306009_wp, 0.09472530522753424814233_wp, &
      0.09472530522753424814233_wp, 0.09130170752246179306009_wp, &
      0.08457825969750126909095_wp, 0.07479799440828836604818_wp, &
      0.06231448562776693602624_wp, 0.04757925584124639240497_wp, &
      0.03112676196932394643142_wp, 0.01357622970587704742589_wp]

   !> Gauss-Legendre nodes and weights on [-1, 1], the barycentric weights of the nodes
   !> and the differentiation matrix of the interpolating polynomial (d(j, l): weight of
   !> value l in the derivative at node j).
   type :: gl_rule_type
      integer :: n = 0
      real(wp), allocatable :: x(:), w(:), bw(:), d(:, :)
      !> Legendre coefficients of the interpolant from the values at the nodes: c = leg f
      real(wp), allocatable :: leg(:, :)
   end type gl_rule_type

   !> Methods of wa_quad_psi_k
   integer, parameter :: quad_psi_qaws = 1, quad_psi_qag = 2, quad_psi_qags = 3

   !> (E1) coefficients for the GSL callback.
   type :: e1_coef
      real(wp) :: a1, b1, a2, b2
   end type e1_coef

   !> The Psi_c integrand's k^2, sin^2 s, 1 - k^2, cos^2 s (GSL's context pointer).
   type :: psi_zone
      real(wp) :: k2, s2, omk2, cs2
   end type psi_zone

contains

   ! ------------------------------------------------------------------ DW: W

   !> W by the Carlson form (istar_carlson); NaN where GSL fails.
   function wa_quad_istar_carlson(a, c, d2, omc2) result(w) bind(C, name="wa_quad_istar_carlson")
      real(c_double), value, intent(in) :: a, c, d2, omc2
      real(c_double) :: w
      type(c_funptr) :: previous
      integer :: status
      previous = gsl_set_error_handler_off()
      call istar_carlson(a, c, d2, omc2, w, status)
      if (status /= wa_ok) w = ieee_value(w, ieee_quiet_nan)
   end function wa_quad_istar_carlson

   !> W by GSL QAG (GK21) of (E1): int_0^(pi/2) s^2 k^2 sqrt(a1 k^2 + b1 s^2)/sqrt(a2 k^2 +
   !> b2 s^2) dphi, a1 = 1-C^2, b1 = 1-A^2, a2 = C^2, b2 = A^2; epsrel max(tol, 1.2e-14).
   function wa_quad_istar_qag(a, c, d2, omc2, tol) result(w) bind(C, name="wa_quad_istar_qag")
      real(c_double), value, intent(in) :: a, c, d2, omc2, tol
      real(c_double) :: w
      type(e1_coef), target :: coef
      real(c_double) :: res, err
      type(gsl_function) :: f
      type(c_ptr) :: work
      type(c_funptr) :: previous
      integer(c_int) :: st
      integer(c_size_t), parameter :: limit = 200
      previous = gsl_set_error_handler_off()
      coef = e1_coef(omc2, d2 + omc2, c**2, a**2)
      work = gsl_integration_workspace_alloc(limit)
      f%function = c_funloc(e1_integrand)
      f%params = c_loc(coef)
      st = gsl_integration_qag(f, 0.0_c_double, real(0.5_wp*pi, c_double), 0.0_c_double, &
         max(tol, 1.2e-14_wp), limit, 2_c_int, work, res, err)
      call gsl_integration_workspace_free(work)
      w = res
      if (st /= 0) w = ieee_value(w, ieee_quiet_nan)
   end function wa_quad_istar_qag

   function e1_integrand(phi, ctx) result(f) bind(C, name="wa_quad_e1_integrand")
      real(c_double), value :: phi
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(e1_coef), pointer :: q
      real(wp) :: s, k
      call c_f_pointer(ctx, q)
      s = sin(phi)
      k = cos(phi)
      f = (s*k)**2*sqrt(q%a1*k**2 + q%b1*s**2)/sqrt(q%a2*k**2 + q%b2*s**2)
   end function e1_integrand

   ! ------------------------------------------------------------------ MD: K of Psi_c

   !> psi_k_gsl's K alone, for the pure interface quad_psi_k.
   function wa_quad_psi_k(method, k2, s2, omk2, cs2, tol) result(total) &
         bind(C, name="wa_quad_psi_k")
      integer(c_int), value, intent(in) :: method
      real(c_double), value, intent(in) :: k2, s2, omk2, cs2, tol
      real(c_double) :: total
      integer :: gsl_status
      call psi_k_gsl(int(method), k2, s2, omk2, cs2, tol, total, gsl_status)
      if (gsl_status /= 0) total = ieee_value(total, ieee_quiet_nan)
   end function wa_quad_psi_k

   !> K by GSL: method quad_psi_qaws (QAWS with weight ln(1-r) plus QAG for the ln(1+r)
   !> part), quad_psi_qag (QAG, GK21) or quad_psi_qags (QAGS) of the whole integrand;
   !> epsrel tol, epsabs 0. NaN for an unknown method. gsl_status: 0, or the non-zero
   !> status of the last GSL call that failed (total is then what GSL returned).
   subroutine psi_k_gsl(method, k2, s2, omk2, cs2, tol, total, gsl_status)
      integer, intent(in) :: method
      real(wp), intent(in) :: k2, s2, omk2, cs2, tol
      real(wp), intent(out) :: total
      integer, intent(out) :: gsl_status
      type(psi_zone), target :: z
      real(c_double) :: r1, r2, err
      type(gsl_function) :: f
      type(c_ptr) :: work, table
      type(c_funptr) :: previous
      integer(c_int) :: st, st2
      integer(c_size_t), parameter :: limit = 1000

      st = 0
      z = psi_zone(k2, s2, omk2, cs2)
      previous = gsl_set_error_handler_off()
      work = gsl_integration_workspace_alloc(limit)
      f%params = c_loc(z)
      select case (method)
      case (quad_psi_qaws)
         table = gsl_integration_qaws_table_alloc(0.0_c_double, 0.0_c_double, 0_c_int, 1_c_int)
         f%function = c_funloc(f_rg)
         st = gsl_integration_qaws(f, 0.0_c_double, 1.0_c_double, table, 0.0_c_double, tol, &
            limit, work, r1, err)
         f%function = c_funloc(f_log1p_rg)
         st2 = gsl_integration_qag(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
            2_c_int, work, r2, err)
         if (st2 /= 0) st = st2
         call gsl_integration_qaws_table_free(table)
         total = -0.5_wp*r1 + 0.5_wp*r2
      case (quad_psi_qag)
         f%function = c_funloc(f_full)
         st = gsl_integration_qag(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
            2_c_int, work, total, err)
      case (quad_psi_qags)
         f%function = c_funloc(f_full)
         st = gsl_integration_qags(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
            work, total, err)
      case default
         total = ieee_value(total, ieee_quiet_nan)
      end select
      call gsl_integration_workspace_free(work)
      gsl_status = int(st)
   end subroutine psi_k_gsl

   !> r G(r) with 1 - k^2 r^2 and 1 - sin^2 r^2 formed from 1 - r without cancellation.
   pure function rg(k2, s2, omk2, cs2, r) result(f)
      real(wp), intent(in) :: k2, s2, omk2, cs2, r
      real(wp) :: f, y2
      y2 = (1.0_wp - r)*(1.0_wp + r)
      f = r/((omk2 + k2*y2)*sqrt(cs2 + s2*y2))
   end function rg

   function f_rg(r, ctx) result(f) bind(C, name="wa_quad_psi_rg")
      real(c_double), value :: r
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(psi_zone), pointer :: z
      call c_f_pointer(ctx, z)
      f = rg(z%k2, z%s2, z%omk2, z%cs2, r)
   end function f_rg

   function f_log1p_rg(r, ctx) result(f) bind(C, name="wa_quad_psi_log1p_rg")
      real(c_double), value :: r
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(psi_zone), pointer :: z
      call c_f_pointer(ctx, z)
      f = log(1.0_wp + r)*rg(z%k2, z%s2, z%omk2, z%cs2, r)
   end function f_log1p_rg

   function f_full(r, ctx) result(f) bind(C, name="wa_quad_psi_full")
      real(c_double), value :: r
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(psi_zone), pointer :: z
      call c_f_pointer(ctx, z)
      f = 0.0_wp
      if (r < 1.0_wp) f = 0.5_wp*log((1.0_wp + r)/(1.0_wp - r))*rg(z%k2, z%s2, z%omk2, z%cs2, r)
   end function f_full

   !> K by the rules of psi_gauss_rules: rule(1:2, i) Gauss-Legendre nodes and weights on
   !> [0, 1], rule(3:4, i) those of the Gauss rule for the weight -ln u on [0, 1].
   pure function k_gauss(k2, s2, omk2, cs2, rule) result(total)
      real(wp), intent(in) :: k2, s2, omk2, cs2
      real(wp), intent(in) :: rule(:, :)
      real(wp) :: total
      integer :: i
      total = 0
      do i = 1, size(rule, 2)
         ! weight -ln(u), u = 1 - r:  -(1/2) ln(1-r) r G
         total = total + 0.5_wp*rule(4, i)*rg(k2, s2, omk2, cs2, 1.0_wp - rule(3, i)) &
            + 0.5_wp*rule(2, i)*log(1.0_wp + rule(1, i))*rg(k2, s2, omk2, cs2, rule(1, i))
      end do
   end function k_gauss

   !> The rules of k_gauss with n nodes each (n >= 1).
   pure subroutine psi_gauss_rules(n, rule)
      integer, intent(in) :: n
      real(wp), intent(out) :: rule(4, n)
      call gauss_legendre01(n, rule(1, :), rule(2, :))
      call gauss_log01(n, rule(3, :), rule(4, :))
   end subroutine psi_gauss_rules

   !> Gauss-Legendre on [0, 1] (Newton on P_n).
   pure subroutine gauss_legendre01(n, x, w)
      integer, intent(in) :: n
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: z, p0, p1, p2, dp
      integer :: i, j, it
      do i = 1, n
         z = cos(pi*(i - 0.25_wp)/(n + 0.5_wp))
         do it = 1, 100
            p0 = 1; p1 = z
            do j = 2, n
               p2 = ((2*j - 1)*z*p1 - (j - 1)*p0)/j
               p0 = p1; p1 = p2
            end do
            dp = n*(z*p1 - p0)/(z*z - 1)
            z = z - p1/dp
            if (abs(p1/dp) < 1e-16_wp) exit
         end do
         x(i) = 0.5_wp*(1 - z)
         w(i) = 1/((1 - z*z)*dp*dp)
      end do
   end subroutine gauss_legendre01

   !> Gauss rule for the weight -ln(u) on [0, 1] from its modified moments against
   !> shifted Legendre polynomials (modified Chebyshev algorithm, Gautschi), then
   !> eigenvalues of the Jacobi matrix by the implicit QL algorithm.
   pure subroutine gauss_log01(n, x, w)
      integer, intent(in) :: n
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: alpha(n), beta(n)
      call log_recurrence(n, alpha, beta)
      call golub_welsch(n, alpha, beta, x, w)
   end subroutine gauss_log01

   !> Recurrence coefficients of the orthogonal polynomials for -ln(u) on [0, 1]
   !> (modified Chebyshev algorithm with shifted monic Legendre polynomials).
   pure subroutine log_recurrence(n, alpha, beta)
      integer, intent(in) :: n
      real(wp), intent(out) :: alpha(n), beta(n)
      real(wp) :: mom(0:2*n - 1), a(0:2*n - 1), b(0:2*n - 1)
      real(wp) :: sig(-1:2*n, 0:2*n)
      integer :: k, l
      real(wp) :: c
      ! monic shifted Legendre on [0,1]: a_k = 1/2, b_k = k^2/(4(4k^2-1))
      do k = 0, 2*n - 1
         a(k) = 0.5_wp
         b(k) = merge(1.0_wp, real(k, wp)**2/(4*(4*real(k, wp)**2 - 1)), k == 0)
      end do
      ! modified moments of -ln u against monic shifted Legendre pi_k:
      ! int -ln(u) P*_k(u) du = (-1)^k/(k(k+1)), P*_k = ((2k)!/(k!)^2) pi_k, so
      ! m_k = (-1)^k (k!)^2/((2k)! k (k+1)) for k >= 1, m_0 = 1
      mom(0) = 1
      c = 1
      do k = 1, 2*n - 1
         c = c*real(k, wp)/real(2*(2*k - 1), wp)     ! (k!)^2/(2k)! recursively
         mom(k) = (-1)**k*c/real(k*(k + 1), wp)
      end do
      sig = 0
      sig(0, 0:2*n - 1) = mom(0:2*n - 1)
      alpha(1) = a(0) + mom(1)/mom(0)
      beta(1) = mom(0)
      do k = 1, n - 1
         do l = k, 2*n - k - 1
            sig(k, l) = sig(k - 1, l + 1) - (alpha(k) - a(l))*sig(k - 1, l) &
               - beta(k)*merge(0.0_wp, sig(k - 2, l), k < 2) + b(l)*sig(k - 1, l - 1)
         end do
         alpha(k + 1) = a(k) + sig(k, k + 1)/sig(k, k) - sig(k - 1, k)/sig(k - 1, k - 1)
         beta(k + 1) = sig(k, k)/sig(k - 1, k - 1)
      end do
   end subroutine log_recurrence

   !> Nodes and weights from the Jacobi matrix (symmetric tridiagonal QL, tqli-style).
   pure subroutine golub_welsch(n, alpha, beta, x, w)
      integer, intent(in) :: n
      real(wp), intent(in) :: alpha(n), beta(n)
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: d(n), e(n), zz(n), gg, r, s, c, p, f, b
      integer :: l, m, i, iter
      d = alpha
      e(1:n - 1) = sqrt(beta(2:n)); e(n) = 0
      zz = 0; zz(1) = 1
      r = 0; i = 0
      do l = 1, n
         iter = 0
         do
            do m = l, n - 1
               if (abs(e(m)) <= epsilon(1.0_wp)*(abs(d(m)) + abs(d(m + 1)))) exit
            end do
            if (m == l) exit
            iter = iter + 1
            gg = (d(l + 1) - d(l))/(2*e(l)); r = hypot(gg, 1.0_wp)
            gg = d(m) - d(l) + e(l)/(gg + sign(r, gg))
            s = 1; c = 1; p = 0
            do i = m - 1, l, -1
               f = s*e(i); b = c*e(i)
               r = hypot(f, gg); e(i + 1) = r
               if (r == 0) then
                  d(i + 1) = d(i + 1) - p; e(m) = 0; exit
               end if
               s = f/r; c = gg/r; gg = d(i + 1) - p
               r = (d(i) - gg)*s + 2*c*b; p = s*r; d(i + 1) = gg + p; gg = c*r - b
               f = zz(i + 1); zz(i + 1) = s*zz(i) + c*f; zz(i) = c*zz(i) - s*f
            end do
            if (r == 0 .and. i >= l) cycle
            d(l) = d(l) - p; e(l) = gg; e(m) = 0
         end do
      end do
      x = d; w = beta(1)*zz**2
      call sort2(x, w)
   end subroutine golub_welsch

   !> Sort x increasing, carrying w along (insertion sort: n <= a few hundred).
   pure subroutine sort2(x, w)
      real(wp), intent(inout) :: x(:), w(:)
      integer :: i, j
      real(wp) :: vx, vw
      do i = 2, size(x)
         vx = x(i); vw = w(i); j = i - 1
         do while (j >= 1)
            if (x(j) <= vx) exit
            x(j + 1) = x(j); w(j + 1) = w(j); j = j - 1
         end do
         x(j + 1) = vx; w(j + 1) = vw
      end do
   end subroutine sort2

   ! ------------------------------- Gauss-Legendre rules with their interpolants

   !> Gauss-Legendre rule with n nodes, its barycentric weights and differentiation matrix.
   pure subroutine gl_rule(n, rule)
      integer, intent(in) :: n
      type(gl_rule_type), intent(out) :: rule
      integer :: j, l
      real(wp) :: p0(n), p1(n), p2(n)
      rule%n = n
      allocate (rule%x(n), rule%w(n), rule%bw(n), rule%d(n, n), rule%leg(n, n))
      call gauss_legendre_pm1(rule%x, rule%w)
      p0 = 1.0_wp; p1 = rule%x                    ! P_k(x_j) by the three-term recurrence
      rule%leg(1, :) = 0.5_wp*rule%w
      if (n > 1) rule%leg(2, :) = 1.5_wp*rule%w*p1
      do l = 2, n - 1
         p2 = (real(2*l - 1, wp)*rule%x*p1 - real(l - 1, wp)*p0)/real(l, wp)
         rule%leg(l + 1, :) = 0.5_wp*real(2*l + 1, wp)*rule%w*p2
         p0 = p1; p1 = p2
      end do
      do j = 1, n
         rule%bw(j) = 1.0_wp
         do l = 1, n
            if (l /= j) rule%bw(j) = rule%bw(j)/(rule%x(j) - rule%x(l))
         end do
      end do
      rule%d = 0.0_wp
      do j = 1, n
         do l = 1, n
            if (l == j) cycle
            rule%d(j, l) = (rule%bw(l)/rule%bw(j))/(rule%x(j) - rule%x(l))
            rule%d(j, j) = rule%d(j, j) - rule%d(j, l)
         end do
      end do
   end subroutine gl_rule

   !> The interpolating polynomial through (rule%x, f) at z in [-1, 1] (barycentric).
   pure real(wp) function gl_interpolate(rule, f, z) result(v)
      type(gl_rule_type), intent(in) :: rule
      real(wp), intent(in) :: f(:), z
      real(wp) :: num, den, t
      integer :: j
      num = 0.0_wp; den = 0.0_wp
      do j = 1, rule%n
         if (z == rule%x(j)) then
            v = f(j)
            return
         end if
         t = rule%bw(j)/(z - rule%x(j))
         num = num + t*f(j); den = den + t
      end do
      v = num/den
   end function gl_interpolate

   !> The interpolant of p and dp/dg = (dp/dz)/(dg/dz) at z.
   pure subroutine gl_value_slope(rule, p, g, z, v, dpdg)
      type(gl_rule_type), intent(in) :: rule
      real(wp), intent(in) :: p(:), g(:), z
      real(wp), intent(out) :: v, dpdg
      real(wp) :: zz, dp, dg, gz, t, den
      integer :: j
      zz = z
      if (any(zz == rule%x)) zz = zz + 8.0_wp*epsilon(zz)*merge(-1.0_wp, 1.0_wp, zz > 0.0_wp)
      v = gl_interpolate(rule, p, zz)
      gz = gl_interpolate(rule, g, zz)
      dp = 0.0_wp; dg = 0.0_wp; den = 0.0_wp
      do j = 1, rule%n                               ! Schneider-Werner derivative
         t = rule%bw(j)/(zz - rule%x(j))
         den = den + t
         dp = dp + t*(v - p(j))/(zz - rule%x(j))
         dg = dg + t*(gz - g(j))/(zz - rule%x(j))
      end do
      dpdg = 0.0_wp
      if (dg /= 0.0_wp) dpdg = dp/dg
   end subroutine gl_value_slope

   !> z in [-1, 1] where the (monotone) interpolant of g equals target: bisection
   !> safeguarded Newton-secant (regula falsi with the Illinois rule).
   pure real(wp) function gl_invert(rule, g, target) result(z)
      type(gl_rule_type), intent(in) :: rule
      real(wp), intent(in) :: g(:), target
      real(wp) :: za, zb, fa, fb, fz
      integer :: it, side
      za = -1.0_wp; zb = 1.0_wp
      fa = gl_interpolate(rule, g, za) - target
      fb = gl_interpolate(rule, g, zb) - target
      if (fa == 0.0_wp) then
         z = za; return
      else if (fb == 0.0_wp .or. fa*fb > 0.0_wp) then
         z = merge(za, zb, abs(fa) < abs(fb)); return
      end if
      side = 0
      z = za
      do it = 1, 200
         z = (za*fb - zb*fa)/(fb - fa)
         if (.not. (z > za .and. z < zb)) z = 0.5_wp*(za + zb)
         fz = gl_interpolate(rule, g, z) - target
         if (fz == 0.0_wp .or. zb - za <= 4.0_wp*epsilon(1.0_wp)) exit
         if (fz*fb > 0.0_wp) then
            zb = z; fb = fz
            if (side == 1) fa = 0.5_wp*fa
            side = 1
         else
            za = z; fa = fz
            if (side == -1) fb = 0.5_wp*fb
            side = -1
         end if
         if (abs(zb - za) <= 2.0_wp*epsilon(1.0_wp)*max(1.0_wp, abs(z))) exit
      end do
   end function gl_invert

   !> Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n).
   pure subroutine gauss_legendre_pm1(x, w)
      real(wp), intent(out) :: x(:), w(:)
      integer :: n, i, k, it
      real(wp) :: z, p0, p1, p2, dp
      n = size(x)
      do i = 1, n
         z = cos(pi*(real(i, wp) - 0.25_wp)/(real(n, wp) + 0.5_wp))
         do it = 1, 100
            p0 = 1.0_wp; p1 = z
            do k = 2, n
               p2 = (real(2*k - 1, wp)*z*p1 - real(k - 1, wp)*p0)/real(k, wp)
               p0 = p1; p1 = p2
            end do
            dp = real(n, wp)*(z*p1 - p0)/(z*z - 1.0_wp)
            if (abs(p1/dp) < 1.0e-16_wp) exit
            z = z - p1/dp
         end do
         x(i) = z
         w(i) = 2.0_wp/((1.0_wp - z*z)*dp*dp)
      end do
   end subroutine gauss_legendre_pm1

end module wa_quadrature
