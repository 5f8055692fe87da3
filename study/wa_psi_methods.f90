!> The alternative ways to compute the MD Psi_c integral that the library does not use
!> (src/wa_md.f90 sums fixed graded Gauss rules), shared by the work-precision study
!> (study/wa_study_md.f90) and tools/md_quadrature_study.f90. All integrate
!>   K = int_0^1 artanh(r) r G(r) dr,  G = 1/((1 - k^2 r^2) sqrt(1 - sin^2 s r^2)):
!>   k_gauss     one Gauss rule for the weight -ln(1-r) plus Gauss-Legendre for ln(1+r)
!>   k_qaws      GSL QAWS (weight ln(1-r)) + GSL QAG for the ln(1+r) part
!>   k_adaptive  GSL QAG or QAGS on the whole integrand
!> Study code, not library code: the Gauss rules are built once into module arrays.
module wa_psi_methods
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_ptr, c_size_t, c_funloc, &
      c_loc, c_f_pointer
   use wa_kinds, only: wp, pi
   use wa_gsl, only: gsl_function, gsl_integration_workspace_alloc, &
      gsl_integration_workspace_free, gsl_integration_qaws_table_alloc, &
      gsl_integration_qaws_table_free, gsl_integration_qaws, gsl_integration_qag, &
      gsl_integration_qags
   implicit none
   private

   public :: psi_zone, init_psi_rules, k_gauss, k_qaws, k_adaptive, max_nodes, sort2

   !> The integrand's parameters k^2, sin^2 s, 1 - k^2, cos^2 s (GSL's context pointer).
   type :: psi_zone
      real(wp) :: k2, s2, omk2, cs2
   end type psi_zone

   integer, parameter :: max_nodes = 64
   !> Gauss-Legendre and Gauss-log rules on [0, 1], by number of nodes (16, 32, 48, 64)
   real(wp), save :: xg(max_nodes, max_nodes) = 0, wg(max_nodes, max_nodes) = 0
   real(wp), save :: xl(max_nodes, max_nodes) = 0, wl(max_nodes, max_nodes) = 0

contains

   !> Build the Gauss rules with 16, 32, 48, 64 nodes (call once before k_gauss).
   subroutine init_psi_rules()
      integer :: n
      do n = 16, max_nodes, 16
         call gauss_legendre01(n, xg(1:n, n), wg(1:n, n))
         call gauss_log01(n, xl(1:n, n), wl(1:n, n))
      end do
   end subroutine init_psi_rules

   !> r G(r) with 1 - k^2 r^2 and 1 - sin^2 r^2 formed from 1 - r without cancellation.
   pure function rg(z, r) result(f)
      type(psi_zone), intent(in) :: z
      real(wp), intent(in) :: r
      real(wp) :: f, y2
      y2 = (1.0_wp - r)*(1.0_wp + r)
      f = r/((z%omk2 + z%k2*y2)*sqrt(z%cs2 + z%s2*y2))
   end function rg

   function k_gauss(z, nodes) result(total)
      type(psi_zone), intent(in) :: z
      integer, intent(in) :: nodes
      real(wp) :: total
      integer :: i
      total = 0
      do i = 1, nodes
         ! weight -ln(u), u = 1 - r:  -(1/2) ln(1-r) r G
         total = total + 0.5_wp*wl(i, nodes)*rg(z, 1.0_wp - xl(i, nodes)) &
            + 0.5_wp*wg(i, nodes)*log(1.0_wp + xg(i, nodes))*rg(z, xg(i, nodes))
      end do
   end function k_gauss

   function k_qaws(z, tol, fails) result(total)
      type(psi_zone), intent(in), target :: z
      real(wp), intent(in) :: tol
      integer, intent(inout), optional :: fails
      real(wp) :: total
      type(gsl_function) :: f
      type(c_ptr) :: work, table
      real(c_double) :: r1, r2, err
      integer(c_int) :: st1, st2
      integer(c_size_t), parameter :: limit = 1000

      work = gsl_integration_workspace_alloc(limit)
      table = gsl_integration_qaws_table_alloc(0.0_c_double, 0.0_c_double, 0_c_int, 1_c_int)
      f%params = c_loc(z)
      f%function = c_funloc(f_rg)
      st1 = gsl_integration_qaws(f, 0.0_c_double, 1.0_c_double, table, 0.0_c_double, tol, &
         limit, work, r1, err)
      f%function = c_funloc(f_log1p_rg)
      st2 = gsl_integration_qag(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
         2_c_int, work, r2, err)
      if ((st1 /= 0 .or. st2 /= 0) .and. present(fails)) fails = fails + 1
      call gsl_integration_qaws_table_free(table)
      call gsl_integration_workspace_free(work)
      total = -0.5_wp*r1 + 0.5_wp*r2
   end function k_qaws

   function k_adaptive(z, extrapolate, tol, fails) result(total)
      type(psi_zone), intent(in), target :: z
      logical, intent(in) :: extrapolate
      real(wp), intent(in) :: tol
      integer, intent(inout), optional :: fails
      real(wp) :: total
      type(gsl_function) :: f
      type(c_ptr) :: work
      real(c_double) :: err
      integer(c_int) :: st
      integer(c_size_t), parameter :: limit = 1000

      work = gsl_integration_workspace_alloc(limit)
      f%params = c_loc(z)
      f%function = c_funloc(f_full)
      if (.not. extrapolate) then
         st = gsl_integration_qag(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
            2_c_int, work, total, err)
      else
         st = gsl_integration_qags(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
            work, total, err)
      end if
      if (st /= 0 .and. present(fails)) fails = fails + 1
      call gsl_integration_workspace_free(work)
   end function k_adaptive

   function f_rg(r, ctx) result(f) bind(C)
      real(c_double), value :: r
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(psi_zone), pointer :: z
      call c_f_pointer(ctx, z)
      f = rg(z, r)
   end function f_rg

   function f_log1p_rg(r, ctx) result(f) bind(C)
      real(c_double), value :: r
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(psi_zone), pointer :: z
      call c_f_pointer(ctx, z)
      f = log(1.0_wp + r)*rg(z, r)
   end function f_log1p_rg

   function f_full(r, ctx) result(f) bind(C)
      real(c_double), value :: r
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(psi_zone), pointer :: z
      call c_f_pointer(ctx, z)
      f = 0.0_wp
      if (r < 1.0_wp) f = 0.5_wp*log((1.0_wp + r)/(1.0_wp - r))*rg(z, r)
   end function f_full

   !> Gauss-Legendre on [0, 1] (Newton on P_n).
   subroutine gauss_legendre01(n, x, w)
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
   subroutine gauss_log01(n, x, w)
      integer, intent(in) :: n
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: alpha(n), beta(n)
      call log_recurrence(n, alpha, beta)
      call golub_welsch(n, alpha, beta, x, w)
   end subroutine gauss_log01

   !> Recurrence coefficients of the orthogonal polynomials for -ln(u) on [0, 1]
   !> (modified Chebyshev algorithm with shifted monic Legendre polynomials).
   subroutine log_recurrence(n, alpha, beta)
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
   subroutine golub_welsch(n, alpha, beta, x, w)
      integer, intent(in) :: n
      real(wp), intent(in) :: alpha(n), beta(n)
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: d(n), e(n), zz(n), gg, r, s, c, p, f, b
      integer :: l, m, i, iter
      d = alpha
      e(1:n - 1) = sqrt(beta(2:n)); e(n) = 0
      zz = 0; zz(1) = 1
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

   subroutine sort2(x, w)
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

end module wa_psi_methods
