!> display: none
!>
!> The periodic elastic half-space of the smooth-adhesion model on a uniform grid, in the
!> library's units (x/L, heights/Delta, pressures/p*): the displacement of the Fourier
!> mode k is u_k = p_k/|k| (doc/theory.md, "Smooth adhesion"), so the stiffness of the
!> nodal values (trigonometric interpolation, Nyquist mode included) is the circulant
!>   K(0) = N/4,  K(m) = 0 (m even),  K(m) = -1/(N sin^2(pi m/N)) (m odd).
!> An even profile is solved on the half period (nodes 0..N/2, the interior ones counted
!> twice); any other on the whole period.
module wa_bem_elastic
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_invalid_argument, set_error
   implicit none
   private

   public :: bem_grid_type, new_grid, stiffness_matrix, kernel_value, measure_below, &
      peak_value, full_period

   !> The grid and the profile on it.
   type :: bem_grid_type
      !> Points per period N (even) and unknowns n (N/2 + 1 on an even profile, else N)
      integer :: n_period = 0, n = 0
      logical :: even = .true.
      !> Node positions x/L, weights (nodes of the period each unknown stands for), profile
      real(wp), allocatable :: x(:), w(:), f(:)
      !> Mean of the profile over the period
      real(wp) :: fbar = 0.0_wp
   end type bem_grid_type

contains

   !> Grid of n_period points per period; profile: samples of one period at x = j/M
   !> (heights over Delta), resampled spectrally; default 1 - cos(2 pi x).
   pure subroutine new_grid(n_period, grid, status, errmsg, profile)
      integer, intent(in) :: n_period
      type(bem_grid_type), intent(out) :: grid
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), intent(in), optional :: profile(:)
      integer :: i, nn
      character(len=12) :: text

      if (n_period < 8 .or. mod(n_period, 2) /= 0) then
         write (text, '(i0)') n_period
         call set_error(wa_invalid_argument, "n = "//trim(text)//" is outside its valid "// &
            "range: 0 (automatic) or even and >= 8 (grid points per period)", status, errmsg)
         return
      end if
      grid%n_period = n_period
      grid%even = .true.
      if (present(profile)) then
         if (size(profile) < 4) then
            call set_error(wa_invalid_argument, "profile must hold at least 4 samples of "// &
               "one period", status, errmsg)
            return
         end if
         ! a sample that is not finite would reach the resampling and the solver (a crash)
         if (.not. all(ieee_is_finite(profile))) then
            call set_error(wa_invalid_argument, "profile: every sample must be a finite "// &
               "number (height over Delta)", status, errmsg)
            return
         end if
         grid%even = is_even(profile)
      end if
      nn = n_period
      if (grid%even) nn = n_period/2 + 1
      grid%n = nn
      allocate (grid%x(nn), grid%w(nn), grid%f(nn))
      do i = 1, nn
         grid%x(i) = real(i - 1, wp)/n_period
      end do
      grid%w = 1.0_wp
      if (grid%even) grid%w(2:nn - 1) = 2.0_wp
      if (present(profile)) then
         call resample(profile, grid%x, n_period, grid%f)
      else
         grid%f = 1.0_wp - cos(2.0_wp*pi*grid%x)
      end if
      grid%fbar = sum(grid%w*grid%f)/n_period
      status = wa_ok
   end subroutine new_grid

   !> Even within rounding: y(j) = y(M - j).
   pure logical function is_even(y)
      real(wp), intent(in) :: y(:)
      integer :: m, j
      real(wp) :: scale
      m = size(y)
      scale = max(maxval(abs(y)), tiny(1.0_wp))
      is_even = .true.
      do j = 1, m - 1
         if (abs(y(j + 1) - y(m - j + 1)) > 1.0e-12_wp*scale) is_even = .false.
      end do
   end function is_even

   !> Trigonometric interpolant of the samples y (one period) at x, truncated to the
   !> modes the grid of n_period points carries.
   pure subroutine resample(y, x, n_period, f)
      real(wp), intent(in) :: y(:), x(:)
      integer, intent(in) :: n_period
      real(wp), intent(out) :: f(:)
      integer :: m, k, j, kmax
      real(wp) :: ak, bk, arg, wk
      m = size(y)
      kmax = min(m/2, n_period/2)
      f = sum(y)/m
      do k = 1, kmax
         ak = 0.0_wp; bk = 0.0_wp
         do j = 1, m
            arg = 2.0_wp*pi*real(k, wp)*real(j - 1, wp)/m
            ak = ak + y(j)*cos(arg)
            bk = bk + y(j)*sin(arg)
         end do
         wk = 2.0_wp/m
         ! the Nyquist mode of the samples or of the grid is a cosine counted once
         if (2*k == m .or. 2*k == n_period) then
            wk = 1.0_wp/m
            if (2*k == n_period .and. 2*k /= m) wk = 2.0_wp/m
            bk = 0.0_wp
         end if
         f = f + wk*(ak*cos(2.0_wp*pi*k*x) + bk*sin(2.0_wp*pi*k*x))
      end do
   end subroutine resample

   !> K(m) of the circulant nodal stiffness (see the module header).
   elemental function kernel_value(n_period, m) result(k)
      integer, intent(in) :: n_period, m
      real(wp) :: k, s
      integer :: mm
      mm = modulo(m, n_period)
      if (mm == 0) then
         k = 0.25_wp*n_period
      else if (mod(mm, 2) == 0) then
         k = 0.0_wp
      else
         s = sin(pi*real(mm, wp)/n_period)
         k = -1.0_wp/(n_period*s*s)
      end if
   end function kernel_value

   !> The symmetric matrix W K (W: weights) acting on the unknowns: the energy's elastic
   !> Hessian times N. On an even grid K is folded: K(i - j) + K(i + j) for interior j.
   pure subroutine stiffness_matrix(grid, kw)
      type(bem_grid_type), intent(in) :: grid
      real(wp), intent(out) :: kw(:, :)
      real(wp), allocatable :: kv(:)
      integer :: i, j, nn, np
      np = grid%n_period
      nn = grid%n
      allocate (kv(0:np - 1))
      kv = kernel_value(np, [(i, i = 0, np - 1)])
      do j = 1, nn
         do i = 1, nn
            kw(i, j) = kv(modulo(i - j, np))
            if (grid%even .and. j > 1 .and. j < nn) kw(i, j) = kw(i, j) + kv(modulo(i + j - 2, np))
            kw(i, j) = grid%w(i)*kw(i, j)
         end do
      end do
   end subroutine stiffness_matrix

   !> Values of the unknowns on the whole period (an even field unfolded).
   pure function full_period(grid, v) result(g)
      type(bem_grid_type), intent(in) :: grid
      real(wp), intent(in) :: v(:)
      real(wp) :: g(0:grid%n_period - 1)
      integer :: i, np
      np = grid%n_period
      if (grid%even) then
         do i = 0, np/2
            g(i) = v(i + 1)
            if (i > 0) g(np - i) = v(i + 1)
         end do
      else
         g = v(1:np)
      end if
   end function full_period

   !> Measure (fraction of the period) of {x : v(x) <= level}, the crossings placed by
   !> the cubic through the four nearest nodes (error O(dx^4) for a smooth field).
   pure function measure_below(grid, v, level) result(meas)
      type(bem_grid_type), intent(in) :: grid
      real(wp), intent(in) :: v(:), level
      real(wp) :: meas, g(0:grid%n_period - 1), c(4), t
      integer :: j, np, k
      np = grid%n_period
      g = full_period(grid, v) - level
      meas = 0.0_wp
      do j = 0, np - 1
         c = [(g(modulo(j - 2 + k, np)), k = 1, 4)]   ! nodes j-1, j, j+1, j+2
         if (c(2) <= 0.0_wp .and. c(3) <= 0.0_wp) then
            meas = meas + 1.0_wp
         else if (c(2) <= 0.0_wp .or. c(3) <= 0.0_wp) then
            t = cubic_root(c)
            if (c(2) <= 0.0_wp) then
               meas = meas + t
            else
               meas = meas + (1.0_wp - t)
            end if
         end if
      end do
      meas = meas/np
   end function measure_below

   !> Root in (0, 1) of the cubic through (-1, c1), (0, c2), (1, c3), (2, c4), where
   !> c2 and c3 differ in sign (bisection: the sign change brackets it).
   pure function cubic_root(c) result(t)
      real(wp), intent(in) :: c(4)
      real(wp) :: t, lo, hi, flo, fm
      integer :: it
      lo = 0.0_wp; hi = 1.0_wp; flo = c(2)
      do it = 1, 60
         t = 0.5_wp*(lo + hi)
         fm = cubic(c, t)
         if ((fm <= 0.0_wp) .eqv. (flo <= 0.0_wp)) then
            lo = t; flo = fm
         else
            hi = t
         end if
      end do
      t = 0.5_wp*(lo + hi)
   end function cubic_root

   pure function cubic(c, t) result(v)
      real(wp), intent(in) :: c(4), t
      real(wp) :: v
      v = -c(1)*t*(t - 1.0_wp)*(t - 2.0_wp)/6.0_wp + c(2)*(t + 1.0_wp)*(t - 1.0_wp)*(t - 2.0_wp)/2.0_wp &
         - c(3)*(t + 1.0_wp)*t*(t - 2.0_wp)/2.0_wp + c(4)*(t + 1.0_wp)*t*(t - 1.0_wp)/6.0_wp
   end function cubic

   !> Largest (sign = 1) or smallest (sign = -1) value of the field between the nodes:
   !> the maximum of the degree-6 polynomial through the extreme node and three
   !> neighbours on each side (golden section on [-1, 1] nodes; error O(dx^7)).
   pure function peak_value(grid, v, sign) result(vmax)
      type(bem_grid_type), intent(in) :: grid
      real(wp), intent(in) :: v(:)
      integer, intent(in) :: sign
      real(wp) :: vmax, g(0:grid%n_period - 1), c(-3:3), lo, hi, t1, t2, f1, f2
      real(wp), parameter :: r = 0.3819660112501051_wp
      integer :: j, np, k, it
      np = grid%n_period
      g = sign*full_period(grid, v)
      j = maxloc(g, 1) - 1
      c = [(g(modulo(j + k, np)), k = -3, 3)]
      lo = -1.0_wp; hi = 1.0_wp
      t1 = lo + r*(hi - lo); t2 = hi - r*(hi - lo)
      f1 = lagrange7(c, t1); f2 = lagrange7(c, t2)
      do it = 1, 80
         if (f1 < f2) then
            lo = t1; t1 = t2; f1 = f2
            t2 = hi - r*(hi - lo); f2 = lagrange7(c, t2)
         else
            hi = t2; t2 = t1; f2 = f1
            t1 = lo + r*(hi - lo); f1 = lagrange7(c, t1)
         end if
      end do
      vmax = sign*max(c(0), lagrange7(c, 0.5_wp*(lo + hi)))
   end function peak_value

   !> The polynomial through (k, c(k)), k = -3..3, at t.
   pure function lagrange7(c, t) result(p)
      real(wp), intent(in) :: c(-3:3), t
      real(wp) :: p, l
      integer :: i, k
      p = 0.0_wp
      do i = -3, 3
         l = 1.0_wp
         do k = -3, 3
            if (k /= i) l = l*(t - k)/real(i - k, wp)
         end do
         p = p + c(i)*l
      end do
   end function lagrange7

end module wa_bem_elastic
