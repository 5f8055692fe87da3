!> The double-Westergaard (DW) cohesive-zone model at a given contact half-width:
!> equilibria (cases 1-3 of the paper's section 2), traction and gap profiles.
!>
!> Case 1 is solved for s = (C - A)/(1 - A) in (0, 1), with A = sin(pi a*), C = sin(pi c*):
!> C - A = s (1 - A) and 1 - C = (1 - s)(1 - A) then carry no cancellation at either end,
!> however small the zone (large mu: C - A ~ 1e-13) or however close c* is to 1/2.
module wa_dw
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_invalid_argument, wa_no_solution, wa_not_converged, &
      wa_capacity_too_small, wa_numerical_error, set_error
   use wa_validate, only: check_range
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact
   use wa_elliptic, only: istar_scaled, istar_quadrature, ia_star
   use wa_gsl, only: quad_istar_carlson, quad_istar_qag
   use wa_kernels, only: wavy_gap_shape
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_math, only: log1p, sincos_pi
   use wa_separation, only: dw_mean_gap
   implicit none
   private

   public :: dw_equilibrium, dw_roots, dw_residual, dw_state_at, dw_load_at, dw_traction, dw_gap
   public :: dw_options, dw_istar_agm, dw_istar_carlson, dw_istar_tanh_sinh, dw_istar_qag

   !> Ways to compute W = I*/(C^2-A^2)^2 in the residual (doc/accuracy-performance.md):
   !> the closed form by Bartky's AGM (istar_scaled, the default); the Carlson form with
   !> GSL's R_F, R_D, R_J (istar_carlson; (E3) at C = 1, where they diverge); tanh-sinh
   !> quadrature of (E1) (istar_quadrature, which forms C^2-A^2 = (C-A)(C+A) itself);
   !> GSL QAG (Gauss-Kronrod 21) of (E1) on the accurate coefficients (wa_quadrature).
   integer, parameter :: dw_istar_agm = 1, dw_istar_carlson = 2, dw_istar_tanh_sinh = 3, &
      dw_istar_qag = 4

   !> Numerical choices of dw_equilibrium; the defaults are the library's. The others
   !> exist for the work-precision study: each is slower or less accurate.
   type :: dw_options
      !> How W is computed (dw_istar_*)
      integer :: istar_method = dw_istar_agm
      !> Relative tolerance of the quadratures (tanh-sinh: >= 1e-16; QAG: >= 1.2e-14)
      real(wp) :: istar_rtol = 1.0e-15_wp
      !> Brent's absolute tolerance in u = ln s (plus 2 eps |u|)
      real(wp) :: xtol = 4.0_wp*epsilon(1.0_wp)
   end type dw_options

   !> sin(pi a*) and the differences that must not be formed by subtraction.
   type :: contact_geometry
      real(wp) :: a_star, a, one_minus_a, one_minus_a2, cos_a
   end type contact_geometry

   integer, parameter :: max_iterations = 100
   !> Step of the downward walk to the first root, in u = ln s
   real(wp), parameter :: step = log(4.0_wp)
   character(len=*), parameter :: unresolved_zone = "dw: the interaction zone at this "// &
      "a_star is not resolved in double precision (a_star < 1e-150 with C < 1e-100)"
   !> Points of the scan in dw_roots that looks for further sign changes.
   integer, parameter :: scan_points = 48

contains

   !> Principal DW equilibrium at a*: the case-1 state if one exists, else case 2;
   !> a* = 1/2 is full contact at the threshold load P* = 1 - Sigma0/2   (2.29).
   !> options: the numerical choices (dw_options; default: the library's); n_residuals:
   !> the number of residual evaluations (each one W) it took.
   pure subroutine dw_equilibrium(params, a_star, state, status, errmsg, options, n_residuals)
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> Contact half-width over the period, a* = a/L, in [0, 1/2]
      real(wp), intent(in) :: a_star
      !> The principal state (zone case 1, 2, or 3 at a* = 1/2)
      type(state_type), intent(out) :: state
      !> wa_ok; wa_invalid_argument for bad input; wa_not_converged or wa_numerical_error
      !> where the root cannot be resolved in double precision
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      !> The numerical choices (dw_options); default: the library's
      type(dw_options), intent(in), optional :: options
      !> Receives the number of residual evaluations (each one W) the solve took
      integer, intent(out), optional :: n_residuals
      type(dw_options) :: opts
      type(contact_geometry) :: geo
      real(wp) :: g_top, s
      integer :: nres

      nres = 0
      if (present(n_residuals)) n_residuals = 0
      if (present(options)) then
         call check_options(options, status, errmsg)
         if (status /= wa_ok) return
         opts = options
      end if
      call check_range("a_star", a_star, 0.0_wp, 0.5_wp, "[0, 1/2]", status, errmsg)
      if (status /= wa_ok) return
      geo = geometry(a_star)
      if (a_star == 0.5_wp .or. params%sigma0 == 0.0_wp) then
         state = special_state(params, geo)
         return
      end if
      nres = nres + 1
      g_top = residual(params, geo, 0.0_wp, opts)
      if (g_top <= 0.0_wp) then          ! (2.28b) holds: no case-1 root
         state = case2_state(params, geo)
      else
         call solve_case1(params, geo, g_top, opts, s, status, errmsg, nres)
         if (status == wa_ok) state = case1_state(params, geo, s)
      end if
      if (present(n_residuals)) n_residuals = nres
   end subroutine dw_equilibrium

   !> Options in range: a known istar_method, tolerances > 0.
   pure subroutine check_options(options, status, errmsg)
      type(dw_options), intent(in) :: options
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      status = wa_ok
      if (options%istar_method < dw_istar_agm .or. options%istar_method > dw_istar_qag) then
         call set_error(wa_invalid_argument, "dw_options: istar_method must be one of "// &
            "dw_istar_agm, dw_istar_carlson, dw_istar_tanh_sinh, dw_istar_qag (1-4)", &
            status, errmsg)
      else if (.not. (options%istar_rtol > 0.0_wp .and. options%istar_rtol < 1.0_wp)) then
         call set_error(wa_invalid_argument, "dw_options: istar_rtol must be in (0, 1)", &
            status, errmsg)
      else if (.not. (options%xtol > 0.0_wp .and. options%xtol < 1.0_wp)) then
         call set_error(wa_invalid_argument, "dw_options: xtol must be in (0, 1)", &
            status, errmsg)
      end if
   end subroutine check_options

   !> Every DW equilibrium at a*: case-1 roots by increasing c* (each sign change of
   !> the residual on a scan is bracketed and refined), then the case-2 state where
   !> (2.28b) holds. n_roots is the total; if it exceeds size(states), the first ones
   !> are stored and status = wa_capacity_too_small.
   pure subroutine dw_roots(params, a_star, states, n_roots, status, errmsg)
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> Contact half-width over the period, a* = a/L, in [0, 1/2]
      real(wp), intent(in) :: a_star
      !> Receives the states: case-1 roots by increasing c*, then case 2
      type(state_type), intent(inout) :: states(:)
      !> Number of equilibria found (may exceed size(states))
      integer, intent(out) :: n_roots
      !> wa_ok; wa_capacity_too_small when n_roots > size(states); wa_invalid_argument for
      !> bad input; wa_numerical_error where a root cannot be resolved
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: found(scan_points)
      real(wp) :: u(scan_points), g(scan_points), s, g_top
      type(contact_geometry) :: geo
      type(dw_options) :: opts
      integer :: i, nres

      nres = 0
      n_roots = 0
      call check_range("a_star", a_star, 0.0_wp, 0.5_wp, "[0, 1/2]", status, errmsg)
      if (status /= wa_ok) return
      geo = geometry(a_star)
      if (a_star == 0.5_wp .or. params%sigma0 == 0.0_wp) then
         n_roots = 1
         found(1) = special_state(params, geo)
      else
         nres = nres + 1
         g_top = residual(params, geo, 0.0_wp, opts)
         call first_root_floor(params, geo, g_top, opts, nres, u(1), g(1), status, errmsg)
         if (status /= wa_ok) return
         u = scan_abscissae(params, geo, u(1))
         do i = 1, scan_points
            nres = nres + 1
            g(i) = residual(params, geo, u(i), opts)
         end do
         if (any(ieee_is_nan(g))) then
            call set_error(wa_numerical_error, unresolved_zone, status, errmsg)
            return
         end if
         do i = 1, scan_points - 1
            if (g(i)*g(i + 1) > 0.0_wp .or. g(i) == 0.0_wp) cycle
            call refine(params, geo, u(i), g(i), u(i + 1), g(i + 1), opts, s, status, errmsg, &
               nres)
            if (status /= wa_ok) return
            n_roots = n_roots + 1
            found(n_roots) = case1_state(params, geo, s)
         end do
         if (g_top < 0.0_wp) then
            n_roots = n_roots + 1
            found(n_roots) = case2_state(params, geo)
         end if
      end if
      states(1:min(n_roots, size(states))) = found(1:min(n_roots, size(states)))
      if (n_roots > size(states)) then
         call set_error(wa_capacity_too_small, "states: capacity too small for all roots", &
            status, errmsg)
      end if
   end subroutine dw_roots

   !> The case-1 equation (2.25b) as G(u) = ln(lambda (1+lambda) (16/(pi alpha^2)) I*),
   !> u = ln s, s = (C - A)/(1 - A). G < 0 below the root, G(0) is (2.28b)'s left side.
   !> Written as ln(4 Sigma0^2 (C^2-A^2) W (1+1/lambda) / (pi alpha^2 (1-A^2))), with
   !> W = I*/(C^2-A^2)^2, so nothing overflows when lambda is huge.
   pure function dw_residual(params, a_star, u) result(g)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, u
      real(wp) :: g
      g = residual(params, geometry(a_star), u, dw_options())
   end function dw_residual

   !> Total DW surface traction p/p* at x* (period 1) for a solved state:
   !>   (1+lambda) p_W(a) - lambda p_W(c), p_W(a) = 2 cos(pi x) sqrt(A^2 - sin^2(pi x))
   !>   (2.3a), (2.10); 0 where the surfaces are apart and out of range.
   elemental function dw_traction(params, state, x_star) result(p)
      !> The parameters the state was solved with
      type(params_type), intent(in) :: params
      !> A state solved by dw_equilibrium or dw_roots for the same params
      type(state_type), intent(in) :: state
      !> Position over the period, x* = x/L (any real: period 1, crest at 0)
      real(wp), intent(in) :: x_star
      real(wp) :: p
      real(wp) :: a, c, lambda, xr, s, cx

      call state_factors(params, state, a, c, lambda)
      xr = abs(x_star - anint(x_star))
      s = sin(pi*xr)
      cx = cos(pi*xr)
      p = 0.0_wp
      if (s < a) p = 2.0_wp*(1.0_wp + lambda)*cx*sqrt((a - s)*(a + s))
      if (s < c) p = p - 2.0_wp*lambda*cx*sqrt((c - s)*(c + s))
   end function dw_traction

   !> DW gap h/Delta at x* for a solved state: (1+lambda) h_W(a) - lambda h_W(c), where
   !> h_W(a) = 2 [S sqrt(S^2-A^2) - A^2 ln((S+sqrt(S^2-A^2))/A)] (corrected (2.16),
   !> doc/theory.md); zero inside the contact.
   elemental function dw_gap(params, state, x_star) result(h)
      !> The parameters the state was solved with
      type(params_type), intent(in) :: params
      !> A state solved by dw_equilibrium or dw_roots for the same params
      type(state_type), intent(in) :: state
      !> Position over the period, x* = x/L (any real: period 1, crest at 0)
      real(wp), intent(in) :: x_star
      real(wp) :: h
      real(wp) :: a, c, lambda, s

      call state_factors(params, state, a, c, lambda)
      s = sin(pi*abs(x_star - anint(x_star)))
      h = (1.0_wp + lambda)*wavy_gap_shape(a, s) - lambda*wavy_gap_shape(c, s)
   end function dw_gap


   !> The case-1 state at a* on the curve variable u = ln s (no solve): what the
   !> continuation driver needs once its corrector has converged.
   pure function dw_state_at(params, a_star, u) result(state)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, u
      type(state_type) :: state
      state = case1_state(params, geometry(a_star), exp(u))
   end function dw_state_at

   !> P* of dw_state_at alone (the same expression, without the mean gap): what the
   !> continuation's difference stencils need.
   pure real(wp) function dw_load_at(params, a_star, u)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, u
      type(contact_geometry) :: geo
      real(wp) :: c, d2, omc2
      geo = geometry(a_star)
      call zone_of(geo, exp(u), c, d2, omc2)
      dw_load_at = geo%a**2 - 0.5_wp*params%sigma0*sqrt(d2/geo%one_minus_a2)
   end function dw_load_at

   ! ---------------------------------------------------------------- internals

   !> G(u) with W by opts%istar_method (callers count the evaluations in nres).
   pure function residual(params, geo, u, opts) result(g)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: u
      type(dw_options), intent(in) :: opts
      real(wp) :: g
      real(wp), parameter :: lo = 1.0e-75_wp, hi = 1.0e75_wp
      real(wp) :: c, d2, omc2, inv_lambda, k, w

      call zone_of(geo, exp(u), c, d2, omc2)
      inv_lambda = 2.0_wp*sqrt(geo%one_minus_a2)*sqrt(d2)/params%sigma0   ! (2.25b)
      k = 4.0_wp*params%sigma0**2/(pi*params%alpha**2*geo%one_minus_a2)
      if (opts%istar_method == dw_istar_agm) then
         w = istar_scaled(geo%a, c, d2, omc2)
      else
         w = istar_alternative(opts, geo%a, c, d2, omc2)
      end if
      ! one logarithm of the product where no factor can make it overflow or underflow
      if (min(k, d2, w) >= lo .and. max(k, d2, w, inv_lambda) <= hi) then
         g = log(k*d2*w*(1.0_wp + inv_lambda))
      else
         g = log(k) + log(d2) + log(w) + log1p(inv_lambda)
      end if
   end function residual

   !> W by a method of dw_options other than the default (NaN where it fails).
   pure function istar_alternative(opts, a, c, d2, omc2) result(w)
      type(dw_options), intent(in) :: opts
      real(wp), intent(in) :: a, c, d2, omc2
      real(wp) :: w
      integer :: st
      select case (opts%istar_method)
      case (dw_istar_carlson)
         if (omc2 == 0.0_wp) then            ! R_F etc. diverge at C = 1: (E3) instead
            w = ia_star(a, d2)/d2**2
         else
            w = quad_istar_carlson(a, c, d2, omc2)
         end if
      case (dw_istar_tanh_sinh)
         call istar_quadrature(a, c, w, st, rtol=opts%istar_rtol)
      case default
         w = quad_istar_qag(a, c, d2, omc2, opts%istar_rtol)
      end select
   end function istar_alternative

   pure function geometry(a_star) result(geo)
      real(wp), intent(in) :: a_star
      type(contact_geometry) :: geo
      geo%a_star = a_star
      call sincos_pi(a_star, geo%a, geo%cos_a)
      geo%one_minus_a2 = geo%cos_a**2
      geo%one_minus_a = geo%one_minus_a2/(1.0_wp + geo%a)       ! 1 - A = (1 - A^2)/(1 + A)
   end function geometry

   !> C, C^2 - A^2 and 1 - C^2 from s without cancellation.
   pure subroutine zone_of(geo, s, c, d2, omc2)
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: s
      real(wp), intent(out) :: c, d2, omc2
      real(wp) :: d
      if (s >= 1.0_wp) then               ! c* = 1/2 exactly (the case-2 boundary)
         c = 1.0_wp
         d2 = geo%one_minus_a2
         omc2 = 0.0_wp
         return
      end if
      d = s*geo%one_minus_a
      c = min(1.0_wp, geo%a + d)
      d2 = d*(2.0_wp*geo%a + d)
      omc2 = (1.0_wp - s)*geo%one_minus_a*(1.0_wp + c)
   end subroutine zone_of

   !> Bracket the case-1 root in u = ln s around the large-mu estimate
   !> C - A = 2 alpha^2 sqrt(1-A^2)/Sigma0^2 (where G ~ ln s + const), then refine.
   pure subroutine solve_case1(params, geo, g_top, opts, s, status, errmsg, nres)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: g_top
      type(dw_options), intent(in) :: opts
      real(wp), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer, intent(inout) :: nres
      real(wp) :: u_lo, g_lo, u_hi, g_hi

      s = 0.0_wp
      call first_root_floor(params, geo, g_top, opts, nres, u_lo, g_lo, status, errmsg, &
         u_hi, g_hi)
      if (status /= wa_ok) return
      if (u_hi == 0.0_wp .and. u_lo + step < 0.0_wp) then   ! tighten the upper end
         nres = nres + 1
         g_hi = residual(params, geo, u_lo + step, opts)
         if (g_hi >= 0.0_wp) then
            u_hi = u_lo + step
         else
            u_lo = u_lo + step; g_lo = g_hi; g_hi = g_top
         end if
      end if
      call refine(params, geo, u_lo, g_lo, u_hi, g_hi, opts, s, status, errmsg, nres)
   end subroutine solve_case1

   !> A point u_lo below the first case-1 root (G(u_lo) < 0; G -> -inf as s -> 0): from
   !> the large-mu estimate of the root (or s = 1/2), walk down in steps of ln 4.
   !> (u_hi, g_hi): the last point above it (0 and g_top = G(0) if none).
   pure subroutine first_root_floor(params, geo, g_top, opts, nres, u_lo, g_lo, status, &
         errmsg, u_hi, g_hi)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: g_top
      type(dw_options), intent(in) :: opts
      integer, intent(inout) :: nres
      real(wp), intent(out) :: u_lo, g_lo
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), intent(out), optional :: u_hi, g_hi
      real(wp), parameter :: u_floor = log(tiny(1.0_wp))
      real(wp) :: u_prev, g_prev
      integer :: k

      u_prev = 0.0_wp
      g_prev = g_top
      u_lo = min(large_mu_estimate(params, geo), log(0.5_wp))
      status = wa_ok
      do k = 1, 600
         nres = nres + 1
         g_lo = residual(params, geo, u_lo, opts)
         if (ieee_is_nan(g_lo)) exit
         if (g_lo <= 0.0_wp) then
            if (present(u_hi)) u_hi = u_prev
            if (present(g_hi)) g_hi = g_prev
            return
         end if
         u_prev = u_lo; g_prev = g_lo
         u_lo = u_lo - step
         if (u_lo < u_floor) exit
      end do
      if (ieee_is_nan(g_lo)) then
         call set_error(wa_numerical_error, unresolved_zone, status, errmsg)
      else
         call set_error(wa_no_solution, "dw: no case-1 root could be bracketed", &
            status, errmsg)
      end if
   end subroutine first_root_floor

   !> Brent on G(u) over a bracket [u1, u2]; s = exp(root).
   pure subroutine refine(params, geo, u1, g1, u2, g2, opts, s, status, errmsg, nres)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: u1, g1, u2, g2
      type(dw_options), intent(in) :: opts
      real(wp), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer, intent(inout) :: nres
      type(brent_type) :: solver
      real(wp) :: u
      logical :: done
      integer :: iter

      call brent_init(solver, u1, g1, u2, g2, opts%xtol)
      do iter = 1, max_iterations
         call brent_propose(solver, u, done)
         if (done) exit
         nres = nres + 1
         call brent_accept(solver, residual(params, geo, u, opts))
      end do
      s = exp(solver%b)
      if (.not. done) then
         call set_error(wa_not_converged, "dw: case-1 root did not converge", status, errmsg)
      else
         status = wa_ok
      end if
   end subroutine refine

   !> Case-1 state from s: P* = A^2 - (Sigma0/2) sqrt((C^2-A^2)/(1-A^2))   (2.25a)
   pure function case1_state(params, geo, s) result(state)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: s
      type(state_type) :: state
      real(wp) :: c, d2, omc2, cos_c

      call zone_of(geo, s, c, d2, omc2)
      cos_c = sqrt(omc2)
      ! sin(pi(c*-a*)) = (C^2-A^2)/(C cos(pi a*) + A cos(pi c*)): no cancellation
      state%gap_width = atan2(d2/(c*geo%cos_a + geo%a*cos_c), cos_c*geo%cos_a + c*geo%a)/pi
      state%a_star = geo%a_star
      state%c_star = min(nearest(0.5_wp, -1.0_wp), geo%a_star + state%gap_width)  ! c* < 1/2
      state%p_star = geo%a**2 - 0.5_wp*params%sigma0*sqrt(d2/geo%one_minus_a2)
      state%zone_case = zone_inside
      state%gbar = dw_mean_gap(params%sigma0, geo%a, geo%cos_a, c, cos_c, d2)
   end function case1_state

   !> Case 2: c* = 1/2, P* = A^2 - Sigma0/2   (2.28a)
   pure function case2_state(params, geo) result(state)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      type(state_type) :: state
      state%a_star = geo%a_star
      state%c_star = 0.5_wp
      state%gap_width = 0.5_wp - geo%a_star
      state%p_star = geo%a**2 - 0.5_wp*params%sigma0
      state%zone_case = zone_whole_period
      state%gbar = dw_mean_gap(params%sigma0, geo%a, geo%cos_a, 1.0_wp, 0.0_wp, &
         geo%one_minus_a2)
   end function case2_state

   !> a* = 1/2 (full contact at its threshold, (2.29)) and Sigma0 = 0 (Westergaard).
   pure function special_state(params, geo) result(state)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      type(state_type) :: state
      state = case2_state(params, geo)
      if (geo%a_star == 0.5_wp) state%zone_case = zone_full_contact
   end function special_state

   !> A, C and lambda = Sigma0/(2 sqrt(1-A^2) sqrt(C^2-A^2)) of a state   (2.25b)
   pure subroutine state_factors(params, state, a, c, lambda)
      type(params_type), intent(in) :: params
      type(state_type), intent(in) :: state
      real(wp), intent(out) :: a, c, lambda
      real(wp) :: d2
      a = sin(pi*state%a_star)
      c = sin(pi*state%c_star)
      d2 = sin(pi*state%gap_width)*sin(pi*(state%a_star + state%c_star))
      lambda = 0.0_wp
      if (d2 > 0.0_wp .and. state%zone_case /= zone_full_contact) &
         lambda = params%sigma0/(2.0_wp*sin(pi*(0.5_wp - state%a_star))*sqrt(d2))
   end subroutine state_factors

   !> Abscissae u = ln s for the root scan: log-spaced from far below the principal
   !> root up to s -> 1.
   pure function scan_abscissae(params, geo, u_floor) result(u)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      !> A point below the first root (first_root_floor)
      real(wp), intent(in) :: u_floor
      real(wp) :: u(scan_points)
      real(wp) :: u_lo, u_hi
      integer :: i
      u_lo = min(large_mu_estimate(params, geo) - 8.0_wp, log(0.5_wp) - 8.0_wp, u_floor)
      u_hi = log1p(-epsilon(1.0_wp))
      do i = 1, scan_points
         u(i) = u_lo + (u_hi - u_lo)*real(i - 1, wp)/real(scan_points - 1, wp)
      end do
   end function scan_abscissae

   !> ln s at the large-mu root: C - A = 2 alpha^2 sqrt(1-A^2)/Sigma0^2.
   pure function large_mu_estimate(params, geo) result(u)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp) :: u
      u = log(2.0_wp*params%alpha**2*geo%cos_a/params%sigma0**2) - log(geo%one_minus_a)
   end function large_mu_estimate


end module wa_dw
