!> display: none
!>
!> The smooth-adhesion model's operators at large N (doc/theory.md, "Smooth adhesion"):
!> the stiffness applied by FFT (the circulant K is diagonal in Fourier space, its symbol
!> |k|), and a two-grid preconditioner for the unweighted Hessian A = K + diag(sigma')
!> that needs no dense factorisation of the fine grid: Chebyshev-Jacobi smoothing (one
!> FFT product per step) and a coarse-grid correction by the Galerkin operator P^T A P
!> (P: periodic linear interpolation; P^T K P is circulant, P^T diag P tridiagonal),
!> factorised densely on the coarse grid. An uneven field acts on the whole period; an
!> even one on its half (nodes 0..N/2), where the circulant is applied by the type-I
!> cosine transform (the DFT of an even sequence: half the length, real) and the coarse
!> system is folded to its even half.
module wa_bem_fast
   use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_double
   use wa_kinds, only: wp
   use wa_fftw, only: fftw_plan_r2r_1d, fftw_execute_r2r, fftw_destroy_plan, &
      fftw_make_planner_thread_safe, fftw_estimate, fftw_unaligned, fftw_r2hc, fftw_hc2r
   use wa_bem_dense, only: ldl_type, ldl_factor, ldl_solve
   implicit none
   private

   public :: fft_plans_type, plans_create, plans_destroy, circulant_symbol, circulant_apply
   public :: twogrid_type, coarse_stiffness, twogrid_setup, twogrid_apply

   !> The FFTW plans of one period length, owned by the caller's workspace: halfcomplex
   !> there and back on the whole period, or (even) the halfcomplex transform of length np
   !> behind the cosine transform of the half period (dct1).
   type :: fft_plans_type
      integer :: np = 0
      logical :: even = .false.
      type(c_ptr) :: fwd = c_null_ptr, bwd = c_null_ptr
   end type fft_plans_type

   !> A two-grid preconditioner at one state: fine slope, Jacobi scaling (on the half
   !> period where even), coarse factor.
   type :: twogrid_type
      integer :: np = 0, nc = 0, ratio = 0
      logical :: even = .true.
      real(wp), allocatable :: d(:), dinv(:)
      type(ldl_type) :: coarse
   end type twogrid_type

   !> Chebyshev smoothing: degree, and the interval of the Jacobi-scaled spectrum it damps
   !> (the upper end bounds (N/2 + d)/(N/4 + d); the lower end, times the grid ratio, is
   !> the scaled symbol at the coarse grid's Nyquist mode). Degree 2 (four FFT products per
   !> application, six at degree 3) needs more GMRES iterations and refactorisations but
   !> is faster overall: the cycle at N = 512 0.31 s against 0.36 s, N = 4096 3.5 s
   !> against 3.8 s (alpha 0.3, mu 3)
   integer, parameter :: cheb_degree = 2
   real(wp), parameter :: cheb_top = 2.2_wp, cheb_bottom_ratio = 1.5_wp

contains

   !> Plans for the circulants of period np (FFTW_ESTIMATE: no trial runs; measured
   !> planning costs more than the whole cycle at N = 512): the halfcomplex transforms of
   !> length np there and back, or (even) the forward one only, for dct1 (FFTW's own
   !> REDFT00 allocates its buffers at every call, 10 % of the N = 512 cycle in malloc).
   subroutine plans_create(plans, np, even)
      type(fft_plans_type), intent(inout) :: plans
      integer, intent(in) :: np
      !> the fields are even, given on the half period (default false)
      logical, intent(in), optional :: even
      real(c_double), allocatable :: x(:), y(:)
      call plans_destroy(plans)
      if (present(even)) plans%even = even
      call fftw_make_planner_thread_safe()
      allocate (x(np), y(np))
      plans%fwd = fftw_plan_r2r_1d(np, x, y, fftw_r2hc, ior(fftw_estimate, fftw_unaligned))
      if (.not. plans%even) &
         plans%bwd = fftw_plan_r2r_1d(np, y, x, fftw_hc2r, ior(fftw_estimate, fftw_unaligned))
      plans%np = np
   end subroutine plans_create

   subroutine plans_destroy(plans)
      type(fft_plans_type), intent(inout) :: plans
      if (c_associated(plans%fwd)) call fftw_destroy_plan(plans%fwd)
      if (c_associated(plans%bwd)) call fftw_destroy_plan(plans%bwd)
      plans%fwd = c_null_ptr
      plans%bwd = c_null_ptr
      plans%np = 0
      plans%even = .false.
   end subroutine plans_destroy

   !> Eigenvalues over np of the symmetric circulant with first column col (real), in
   !> the halfcomplex order (entry k and np - k both hold the eigenvalue of mode k).
   subroutine circulant_symbol(col, symbol)
      real(wp), intent(in) :: col(0:)
      real(wp), intent(out) :: symbol(0:)
      type(fft_plans_type) :: plans
      real(c_double), allocatable :: x(:), y(:)
      integer :: np, k
      np = size(col)
      call plans_create(plans, np)
      allocate (x(0:np - 1), y(0:np - 1))
      x = col
      call fftw_execute_r2r(plans%fwd, x, y)
      call plans_destroy(plans)
      symbol(0:np/2) = y(0:np/2)/np        ! real parts: the eigenvalues (col is even)
      do k = 1, (np - 1)/2
         symbol(np - k) = symbol(k)
      end do
   end subroutine circulant_symbol

   !> y = C x for the circulant C of the given symbol (circulant_symbol) of period np =
   !> size(symbol): x on the whole period, or an even field on its half (size np/2 + 1).
   subroutine circulant_apply(plans, symbol, x, y)
      type(fft_plans_type), intent(in) :: plans
      real(wp), intent(in) :: symbol(0:), x(0:)
      real(wp), intent(out) :: y(0:)
      type(fft_plans_type) :: own
      logical :: even
      even = size(x) < size(symbol)
      if (c_associated(plans%fwd) .and. plans%np == size(symbol) .and. (plans%even .eqv. even)) then
         call transform(plans, symbol, x, y)
      else                                   ! no plans at hand: make and drop them
         call plans_create(own, size(symbol), even)
         call transform(own, symbol, x, y)
         call plans_destroy(own)
      end if
   end subroutine circulant_apply

   !> circulant_apply with plans that fit: x to Fourier space, times the symbol, back.
   !> For an even field the cosine transform gives the DFT's modes 0..np/2, and applied
   !> again the inverse DFT times np (the symbol holds the eigenvalues over np).
   subroutine transform(plans, symbol, x, y)
      type(fft_plans_type), intent(in) :: plans
      real(wp), intent(in) :: symbol(0:), x(0:)
      real(wp), intent(out) :: y(0:)
      real(c_double) :: xw(size(x)), c(size(x))
      if (plans%even) then
         call dct1(plans, x, c)
         c = c*symbol(0:size(x) - 1)
         call dct1(plans, c, y)
         return
      end if
      xw = x
      call fftw_execute_r2r(plans%fwd, xw, c)
      c = c*symbol(0:size(x) - 1)
      call fftw_execute_r2r(plans%bwd, c, xw)
      y = xw
   end subroutine transform

   !> The type-I cosine transform (FFTW's REDFT00) of x(0:m), m = np/2,
   !>   y(k) = x(0) + (-1)^k x(m) + 2 sum_{j=1}^{m-1} x(j) cos(pi j k/m),
   !> as the real part of the DFT of the even field's whole period (x(j), j = 0..m, then
   !> x(2m-j)) by one halfcomplex transform of length 2m. Not the classical reduction to
   !> length m (Numerical Recipes' cosft1): it gets the odd modes by a running sum of
   !> differences, whose rounding grows with m and, times the stiffness's symbol (up to
   !> N/2), set a floor of 1e-10 on the residual at N = 2048 that stalled Newton.
   subroutine dct1(plans, x, y)
      type(fft_plans_type), intent(in) :: plans
      real(wp), intent(in) :: x(0:)
      real(wp), intent(out) :: y(0:)
      real(c_double) :: u(0:2*size(x) - 3), h(0:2*size(x) - 3)
      integer :: m
      m = size(x) - 1
      u(0:m) = x
      u(m + 1:2*m - 1) = x(m - 1:1:-1)
      call fftw_execute_r2r(plans%fwd, u, h)
      y = h(0:m)
   end subroutine dct1

   !> First column of the coarse circulant P^T K P (coarse period nc = np/ratio) from the
   !> fine circulant's column kcol.
   subroutine coarse_stiffness(kcol, symbol, ratio, kc)
      real(wp), intent(in) :: kcol(0:), symbol(0:)
      integer, intent(in) :: ratio
      real(wp), intent(out) :: kc(0:)
      real(wp), allocatable :: hat(:), v(:)
      type(fft_plans_type) :: none
      integer :: np, f, m
      np = size(kcol)
      allocate (hat(0:np - 1), v(0:np - 1))
      hat = 0.0_wp
      do f = -(ratio - 1), ratio - 1
         hat(modulo(f, np)) = 1.0_wp - real(abs(f), wp)/ratio
      end do
      call circulant_apply(none, symbol, hat, v)
      do m = 0, size(kc) - 1
         kc(m) = 0.0_wp
         do f = -(ratio - 1), ratio - 1
            kc(m) = kc(m) + hat(modulo(f, np))*v(modulo(ratio*m + f, np))
         end do
      end do
   end subroutine coarse_stiffness

   !> The preconditioner at the fine slope d (whole period, unweighted), with the coarse
   !> circulant column kc (coarse_stiffness); even: the fields are even. The coarse
   !> system's negative and zero eigenvalues are counted by its factorisation.
   pure subroutine twogrid_setup(d, kc, ratio, even, tg)
      real(wp), intent(in) :: d(0:), kc(0:)
      integer, intent(in) :: ratio
      logical, intent(in) :: even
      type(twogrid_type), intent(inout) :: tg
      real(wp), allocatable :: a(:, :), t0(:), t1(:)
      integer :: np, nc, i, j, f, jj, m
      real(wp) :: u
      np = size(d)
      nc = np/ratio
      tg%np = np; tg%nc = nc; tg%ratio = ratio; tg%even = even
      if (even) then                   ! the smoother acts on the half period
         tg%d = d(0:np/2)
      else
         tg%d = d
      end if
      tg%dinv = 1.0_wp/(0.25_wp*np + max(tg%d, 0.0_wp))
      allocate (a(0:nc - 1, 0:nc - 1), t0(0:nc - 1), t1(0:nc - 1))
      do j = 0, nc - 1                 ! P^T diag(d) P: diagonal and the super-diagonal
         t0(j) = d(ratio*j)
         t1(j) = 0.0_wp
         do f = 1, ratio - 1
            u = real(f, wp)/ratio
            t0(j) = t0(j) + (1.0_wp - u)**2*d(modulo(ratio*j + f, np)) + &
               u**2*d(modulo(ratio*j - f, np))
            t1(j) = t1(j) + (1.0_wp - u)*u*d(modulo(ratio*j + f, np))
         end do
      end do
      do j = 0, nc - 1
         do i = 0, nc - 1
            a(i, j) = kc(modulo(i - j, nc))
         end do
         a(j, j) = a(j, j) + t0(j)
         a(modulo(j + 1, nc), j) = a(modulo(j + 1, nc), j) + t1(j)
         a(j, modulo(j + 1, nc)) = a(j, modulo(j + 1, nc)) + t1(j)
      end do
      if (even) then                   ! fold onto the even half, weighted: symmetric
         m = nc/2 + 1
         if (allocated(tg%coarse%a)) deallocate (tg%coarse%a)
         allocate (tg%coarse%a(m, m))
         do j = 0, m - 1
            jj = modulo(nc - j, nc)
            do i = 0, m - 1
               tg%coarse%a(i + 1, j + 1) = a(i, j)
               if (j > 0 .and. j < m - 1) tg%coarse%a(i + 1, j + 1) = &
                  tg%coarse%a(i + 1, j + 1) + a(i, jj)
               if (i > 0 .and. i < m - 1) tg%coarse%a(i + 1, j + 1) = 2.0_wp*tg%coarse%a(i + 1, j + 1)
            end do
         end do
      else
         tg%coarse%a = a
      end if
      call ldl_factor(tg%coarse)
   end subroutine twogrid_setup

   !> x ~ A^-1 r (on the whole period, or the half where tg%even): Chebyshev smoothing,
   !> coarse correction, smoothing.
   subroutine twogrid_apply(tg, plans, symbol, r, x)
      type(twogrid_type), intent(in) :: tg
      type(fft_plans_type), intent(in) :: plans
      real(wp), intent(in) :: symbol(0:), r(0:)
      real(wp), intent(out) :: x(0:)
      real(wp) :: res(0:size(r) - 1), dx(0:size(r) - 1)
      call chebyshev(tg, plans, symbol, r, x)
      call apply_a(tg, plans, symbol, x, res)
      res = r - res
      call coarse_correct(tg, res, dx)
      x = x + dx
      call apply_a(tg, plans, symbol, x, res)
      res = r - res
      call chebyshev(tg, plans, symbol, res, dx)
      x = x + dx
   end subroutine twogrid_apply

   !> y = (K + diag d) x (whole period, or half where tg%even).
   subroutine apply_a(tg, plans, symbol, x, y)
      type(twogrid_type), intent(in) :: tg
      type(fft_plans_type), intent(in) :: plans
      real(wp), intent(in) :: symbol(0:), x(0:)
      real(wp), intent(out) :: y(0:)
      call circulant_apply(plans, symbol, x, y)
      y = y + tg%d*x
   end subroutine apply_a

   !> cheb_degree steps of Chebyshev iteration on diag^-1 A x = diag^-1 r from x = 0.
   subroutine chebyshev(tg, plans, symbol, r, x)
      type(twogrid_type), intent(in) :: tg
      type(fft_plans_type), intent(in) :: plans
      real(wp), intent(in) :: symbol(0:), r(0:)
      real(wp), intent(out) :: x(0:)
      real(wp) :: res(0:size(r) - 1), p(0:size(r) - 1), ap(0:size(r) - 1)
      real(wp) :: theta, delta, sigma, rho, rho_new, bottom
      integer :: k
      bottom = cheb_bottom_ratio/tg%ratio
      theta = 0.5_wp*(cheb_top + bottom)
      delta = 0.5_wp*(cheb_top - bottom)
      sigma = theta/delta
      rho = 1.0_wp/sigma
      res = r
      p = tg%dinv*res/theta
      x = 0.0_wp
      do k = 1, cheb_degree
         x = x + p
         if (k == cheb_degree) exit
         call apply_a(tg, plans, symbol, p, ap)
         res = res - ap
         rho_new = 1.0_wp/(2.0_wp*sigma - rho)
         p = rho_new*rho*p + (2.0_wp*rho_new/delta)*tg%dinv*res
         rho = rho_new
      end do
   end subroutine chebyshev

   !> dx = P A_c^-1 P^T res (A_c = P^T A P; res and dx on the half period and A_c on the
   !> even half where tg%even).
   pure subroutine coarse_correct(tg, res, dx)
      type(twogrid_type), intent(in) :: tg
      real(wp), intent(in) :: res(0:)
      real(wp), intent(out) :: dx(0:)
      real(wp) :: rc(0:tg%nc - 1), xc(0:tg%nc), wt(tg%ratio - 1)
      integer :: j, f, r, np, nc, m
      r = tg%ratio; np = tg%np; nc = tg%nc
      wt = [(1.0_wp - real(f, wp)/r, f = 1, r - 1)]
      m = nc
      if (tg%even) m = nc/2 + 1
      do j = 0, m - 1                   ! restriction P^T, on the coarse nodes held
         rc(j) = res(r*j)
         do f = 1, r - 1
            rc(j) = rc(j) + wt(f)*(res(node(r*j + f)) + res(node(r*j - f)))
         end do
      end do
      if (tg%even) then                 ! the even half, interior nodes counted twice
         rc(1:m - 2) = 2.0_wp*rc(1:m - 2)
         call ldl_solve(tg%coarse, rc(0:m - 1))
         xc(0:m - 1) = rc(0:m - 1)
         xc(m) = xc(m - 2)              ! the node past N/2, by symmetry
      else
         xc(0:nc - 1) = rc
         call ldl_solve(tg%coarse, xc(0:nc - 1))
         xc(nc) = xc(0)                 ! periodic
      end if
      do j = 0, (size(dx) - 1)/r        ! prolongation P: linear between coarse nodes
         dx(r*j) = xc(j)
         do f = 1, min(r - 1, size(dx) - 1 - r*j)
            dx(r*j + f) = wt(f)*xc(j) + (1.0_wp - wt(f))*xc(j + 1)
         end do
      end do
   contains
      !> The fine node holding the value at i (periodic; reflected where even)
      pure integer function node(i)
         integer, intent(in) :: i
         node = modulo(i, np)
         if (tg%even .and. node > np/2) node = np - node
      end function node
   end subroutine coarse_correct

end module wa_bem_fast
