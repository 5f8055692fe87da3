!> The Maugis-Dugdale (MD) model of Hui et al. (2001) at a given contact half-width:
!> every equilibrium (cases 1 and 2), the load (2.27a), the opening (2.27b) and Psi_c (2.27d).
!>
!> Unknown. Case 1 (a* < c* < 1/2) is solved in x = ln tan s, where
!>   cos s = tan(pi a*) / tan(pi c*),  s in (0, pi/2),
!> so that, with T = tan s, R = sqrt(1+T^2), q = cos(pi a*), k = chi_3(c*) = q sin s:
!>   chi_1 C = A^2 k/(1-k^2),   chi_2 = artanh k,   1 - k^2 = cos^2 s + A^2 sin^2 s,
!>   1 - (2/pi) arcsin(cos(pi c*)/cos(pi a*)) = (2/pi) atan(A T),
!>   tan(pi (c*-a*)) = A q T^2/(R+1) / (q^2 + A^2 R).
!> Nothing is formed by cancellation: the zone may collapse (large mu: c*-a* ~ 1e-12,
!> x ~ -14) or fill the gap (c* -> 1/2, x -> +inf) and c*-a* keeps full relative accuracy.
!>
!> Psi_c (2.27d) = -(2 A q sin^2 s / pi) K, K a log-singular integral in r = w/k, is summed
!> by wa_md_psi: fixed graded Gauss rules (default, <= 3.2e-15 relative, 1 us), or the
!> alternatives that md_options selects for the work-precision study.
!>
!> Roots. F(x) = opening - Dcod tends to -Dcod as x -> -inf and to a closed form as
!> x -> +inf (c* = 1/2). F is scanned in steps of 0.8 from below the small-zone estimate
!> of the first root up to x_mono, beyond which it is monotone; every sign change is
!> refined by Brent's method (wa_roots) to |dx| <= 4 eps + 2 eps |x|, and at each
!> sampled extremum that could hide a pair of roots a golden-section search looks for
!> the sign change. md_equilibrium stops at the first root.
!>
!> Case 2 (an extension of the paper, doc/theory.md): c* = 1/2, P* = A^2 - Sigma0, valid
!> while the opening at x = L/2 stays within the Dugdale range:
!>   sqrt(1-A^2) - A^2 ln((1 + sqrt(1-A^2))/A) <= Dcod.
module wa_md
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_invalid_argument, wa_no_solution, wa_not_converged, &
      wa_capacity_too_small, wa_numerical_error, set_error
   use wa_validate, only: check_range
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_math, only: log1p, sincos_pi
   use wa_separation, only: md_state_gbar
   use wa_quadrature, only: psi_gauss_rules
   use wa_md_psi, only: md_zone, md_psi_k, md_psi_k_by, md_psi_rules, md_psi_gauss, &
      md_psi_qaws, md_psi_qag, md_psi_qags
   implicit none
   private

   public :: md_equilibrium, md_roots, md_load, md_opening, md_psi_c, md_midgap_opening
   public :: md_curve_residual, md_curve_state, md_curve_values
   !> md_psi_* (the ways to compute Psi_c) are wa_md_psi's, exported with md_options
   public :: md_options, md_prepare_options, md_psi_rules, md_psi_gauss, md_psi_qaws, &
      md_psi_qag, md_psi_qags

   !> Numerical choices of md_equilibrium; the defaults are the library's. The others
   !> exist for the work-precision study: each is slower or less accurate.
   type :: md_options
      !> How Psi_c is computed (md_psi_*)
      integer :: psi_method = md_psi_rules
      !> Nodes of each rule of md_psi_gauss (1-256)
      integer :: psi_nodes = 32
      !> epsrel of the GSL methods (>= 1.1e-14: GSL refuses less)
      real(wp) :: psi_rtol = 1.0e-10_wp
      !> Brent's absolute tolerance in x = ln tan s (plus 2 eps |x|)
      real(wp) :: xtol = 4.0_wp*epsilon(1.0_wp)
      !> The md_psi_gauss rules (md_prepare_options builds them once; without them
      !> md_equilibrium builds them at every call)
      real(wp), allocatable :: gauss_rule(:, :)
   end type md_options

   !> sin and cos of pi a*; for the root scan of `solve` (add_scan_limits) also the
   !> opening at c* = 1/2 and the scan range in x = ln tan s.
   type :: md_geometry
      real(wp) :: a_star = 0.0_wp
      !> A = sin(pi a*), q = cos(pi a*) (from 1/2 - a*, exact near a* = 1/2)
      real(wp) :: a = 0.0_wp, q = 0.0_wp
      !> Opening at x = L/2 with the zone filling the gap: q - A^2 artanh(q)
      real(wp) :: opening_top = 0.0_wp
      !> Beyond x_mono the opening approaches opening_top monotonically;
      !> at x_top, c* rounds to 1/2.
      real(wp) :: x_mono = 0.0_wp, x_top = 0.0_wp
   end type md_geometry

   !> Scan step in x (a factor e^0.8 = 2.2 in tan s) and the golden-section ratio.
   real(wp), parameter :: scan_step = 0.8_wp
   real(wp), parameter :: golden = 0.3819660112501051518_wp
   !> Upper limit of x (T = e^300): c* is then 1/2 to working precision for a* > 1e-120.
   real(wp), parameter :: x_limit = 300.0_wp
   !> Below this a*, the zone could not be resolved in double precision (A^2 underflows
   !> against cos^2 s); such a* return wa_numerical_error.
   real(wp), parameter :: a_star_min = 1.0e-100_wp
   integer, parameter :: max_iterations = 200
   !> Bound on the scan (x from > -650 to x_mono <= x_limit in steps of 0.8: < 1200)
   integer, parameter :: max_scan_points = 2000
   !> At most this many case-1 roots per a* (more: wa_numerical_error; 2 is the most seen).
   integer, parameter :: max_roots = 8


contains

   !> Principal MD equilibrium at a*: the case-1 state with the smallest c*, else the
   !> case-2 state (c* = 1/2, P* = A^2 - Sigma0). a* = 1/2: full contact at the threshold
   !> P* = 1 - Sigma0 (zone_case 3); mu = 0: Westergaard, case 2 with P* = A^2.
   !> a* = 0 (no contact) returns wa_no_solution; so does a* where neither case holds.
   !> 0 < a* < 1e-100 returns wa_numerical_error (not resolved in double precision).
   !> options: the numerical choices (md_options; default: the library's); n_residuals:
   !> the number of residual evaluations (each one Psi_c) it took.
   pure subroutine md_equilibrium(params, a_star, state, status, errmsg, options, n_residuals)
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> Contact half-width over the period, a* = a/L, in (0, 1/2] (0 is no contact:
      !> wa_no_solution; below 1e-100: wa_numerical_error)
      real(wp), intent(in) :: a_star
      !> The principal state (zone case 1, 2, or 3 at a* = 1/2), its mean gap gbar* = mean
      !> gap/Delta filled in; on failure the default state_type (zeros, gbar = -1)
      type(state_type), intent(out) :: state
      !> wa_ok; wa_invalid_argument for bad input; wa_no_solution at a* = 0 or where neither
      !> case holds; wa_not_converged or wa_numerical_error where the root cannot be resolved
      !> in double precision
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      !> The numerical choices (md_options, checked as by md_prepare_options); default: the
      !> library's
      type(md_options), intent(in), optional :: options
      !> Receives the number of residual evaluations (each one Psi_c) the solve took (0 if
      !> the options are refused)
      integer, intent(out), optional :: n_residuals
      type(state_type) :: states(1)
      type(md_options) :: opts
      integer :: n_roots, nres

      nres = 0
      if (present(n_residuals)) n_residuals = 0
      if (present(options)) then
         opts = options
         call md_prepare_options(opts, status, errmsg)
         if (status /= wa_ok) return
      end if
      call solve(params, a_star, .true., opts, nres, states, n_roots, status, errmsg)
      if (status == wa_ok) state = states(1)
      if (status == wa_ok) state%gbar = md_state_gbar(params, state)
      if (present(n_residuals)) n_residuals = nres
   end subroutine md_equilibrium

   !> Check the options (a known psi_method, 1 <= psi_nodes <= 256, tolerances in (0, 1))
   !> and build the md_psi_gauss rules if they are missing.
   pure subroutine md_prepare_options(options, status, errmsg)
      !> The numerical choices to check; receives the md_psi_gauss rules (gauss_rule) when
      !> psi_method is md_psi_gauss and they are missing or of another size; unchanged on
      !> failure
      type(md_options), intent(inout) :: options
      !> wa_ok, or wa_invalid_argument when a field is out of range
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad field and its valid range)
      character(len=*), intent(inout), optional :: errmsg
      status = wa_ok
      if (options%psi_method < md_psi_rules .or. options%psi_method > md_psi_qags) then
         call set_error(wa_invalid_argument, "md_options: psi_method must be one of "// &
            "md_psi_rules, md_psi_gauss, md_psi_qaws, md_psi_qag, md_psi_qags (1-5)", &
            status, errmsg)
      else if (options%psi_nodes < 1 .or. options%psi_nodes > 256) then
         call set_error(wa_invalid_argument, "md_options: psi_nodes must be in [1, 256]", &
            status, errmsg)
      else if (.not. (options%psi_rtol > 0.0_wp .and. options%psi_rtol < 1.0_wp)) then
         call set_error(wa_invalid_argument, "md_options: psi_rtol must be in (0, 1)", &
            status, errmsg)
      else if (.not. (options%xtol > 0.0_wp .and. options%xtol < 1.0_wp)) then
         call set_error(wa_invalid_argument, "md_options: xtol must be in (0, 1)", &
            status, errmsg)
      end if
      if (status /= wa_ok .or. options%psi_method /= md_psi_gauss) return
      if (allocated(options%gauss_rule)) then
         if (size(options%gauss_rule, 2) == options%psi_nodes) return
         deallocate (options%gauss_rule)
      end if
      allocate (options%gauss_rule(4, options%psi_nodes))
      call psi_gauss_rules(options%psi_nodes, options%gauss_rule)
   end subroutine md_prepare_options

   !> Every MD equilibrium at a*: the case-1 roots of (2.27b) by increasing c*, then the
   !> case-2 state where its condition holds. n_roots is the total; if it exceeds
   !> size(states), the first size(states) are stored and status = wa_capacity_too_small.
   !> Status and special a* as for md_equilibrium.
   pure subroutine md_roots(params, a_star, states, n_roots, status, errmsg)
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> Contact half-width over the period, a* = a/L, in (0, 1/2] (as for md_equilibrium)
      real(wp), intent(in) :: a_star
      !> Receives the states, their gbar* filled in: case-1 roots by increasing c*, then case
      !> 2; unchanged on failure (except wa_capacity_too_small: the first size(states))
      type(state_type), intent(inout) :: states(:)
      !> Number of equilibria found (may exceed size(states)); 0 on any other failure
      integer, intent(out) :: n_roots
      !> wa_ok; wa_capacity_too_small when n_roots > size(states); otherwise as for
      !> md_equilibrium
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: found(max_roots + 1)
      type(md_options) :: opts
      integer :: n, nres

      nres = 0
      call solve(params, a_star, .false., opts, nres, found, n_roots, status, errmsg)
      if (status /= wa_ok) return
      n = min(n_roots, size(states), size(found))
      states(1:n) = found(1:n)
      states(1:n)%gbar = md_state_gbar(params, states(1:n))
      if (n_roots > size(states)) then
         call set_error(wa_capacity_too_small, "md_roots: states has room for fewer "// &
            "than all equilibrium states; n_roots is the number needed", status, errmsg)
      end if
   end subroutine md_roots

   !> Load P* of the case-1 state (a*, c* = a* + gap)   (2.27a):
   !>   P* = A^2 - Sigma0 [1 - (2/pi) arcsin(cos(pi c*)/cos(pi a*))].
   !> NaN outside 0 < a* < 1/2, 0 <= gap <= 1/2 - a*.
   elemental function md_load(params, a_star, gap) result(p)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, gap
      real(wp) :: p
      type(md_geometry) :: geo
      real(wp) :: x

      if (.not. valid_zone(a_star, gap)) then
         p = ieee_value(p, ieee_quiet_nan)
         return
      end if
      geo = geometry(a_star)
      x = x_of_gap(geo, gap)
      p = geo%a**2 - params%sigma0*dugdale_fraction(geo, x)
   end function md_load

   !> Left side of (2.27b), the normalised opening at x = c*:
   !>   chi_1 C - P* chi_2 + Sigma0 Psi_c(c*, a*),   c* = a* + gap;
   !> a case-1 equilibrium is where it equals Dcod. NaN outside the domain of md_load.
   elemental function md_opening(params, a_star, gap) result(delta)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, gap
      real(wp) :: delta
      type(md_geometry) :: geo

      if (.not. valid_zone(a_star, gap)) then
         delta = ieee_value(delta, ieee_quiet_nan)
         return
      end if
      geo = geometry(a_star)
      delta = opening(params, geo, x_of_gap(geo, gap))
   end function md_opening

   !> Psi_c(c*, a*) of (2.27d) for c* = a* + gap; -artanh(cos(pi a*)) at c* = 1/2.
   !> NaN outside the domain of md_load.
   elemental function md_psi_c(a_star, gap) result(psi)
      real(wp), intent(in) :: a_star, gap
      real(wp) :: psi
      type(md_geometry) :: geo
      real(wp) :: x

      if (.not. valid_zone(a_star, gap)) then
         psi = ieee_value(psi, ieee_quiet_nan)
         return
      end if
      geo = geometry(a_star)
      x = x_of_gap(geo, gap)
      psi = psi_c(geo, zone_at(geo, x))
   end function md_psi_c

   !> Opening at x = L/2 of the case-2 state, sqrt(1-A^2) - A^2 ln((1+sqrt(1-A^2))/A):
   !> case 2 holds where it is <= Dcod. NaN outside 0 < a* <= 1/2.
   elemental function md_midgap_opening(a_star) result(delta)
      real(wp), intent(in) :: a_star
      real(wp) :: delta
      if (.not. (a_star > 0.0_wp .and. a_star <= 0.5_wp)) then
         delta = ieee_value(delta, ieee_quiet_nan)
         return
      end if
      delta = top_opening(sin(pi*a_star), sin(pi*(0.5_wp - a_star)))
   end function md_midgap_opening


   ! ------------------------------------------------- the curve for continuation

   !> The case-1 residual for the continuation driver in v = ln((c* - a*)/(1/2 - a*))
   !> (v -> 0: c* -> 1/2). The opening is smooth and has a non-zero slope in 1/2 - c* at the
   !> top, so the curve meets v = 0 transversally (in x or in C it would touch it
   !> tangentially), and v keeps the resolution of x for tiny zones:
   !>   ln(opening/Dcod)  (< 0 below the root; at v = 0 it is < 0 exactly where case 2 holds).
   pure function md_curve_residual(params, a_star, v) result(f)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, v
      real(wp) :: f
      type(md_geometry) :: geo
      if (params%sigma0 == 0.0_wp) then             ! mu = 0: Westergaard, case 2 throughout
         f = -1.0_wp
         return
      end if
      geo = geometry(a_star)
      f = curve_residual_at(params, geo, x_of_v(geo, v))
   end function md_curve_residual

   !> md_curve_residual and the P* of md_curve_state at (a*, v) from one geometry and x
   !> (the continuation's difference stencils need both at every node; values identical).
   pure subroutine md_curve_values(params, a_star, v, f, p)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, v
      real(wp), intent(out) :: f, p
      type(md_geometry) :: geo
      real(wp) :: x
      geo = geometry(a_star)
      x = x_of_v(geo, v)
      p = case1_load(params, geo, x)
      if (params%sigma0 == 0.0_wp) then
         f = -1.0_wp
      else
         f = curve_residual_at(params, geo, x)
      end if
   end subroutine md_curve_values

   !> ln(opening/Dcod) at x for Sigma0 > 0 (md_curve_residual's F)
   pure real(wp) function curve_residual_at(params, geo, x)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      curve_residual_at = log(max(opening(params, geo, x), tiny(1.0_wp))/params%dcod)
   end function curve_residual_at

   !> The case-1 state at (a*, v) (no solve).
   pure function md_curve_state(params, a_star, v) result(state)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, v
      type(state_type) :: state
      type(md_geometry) :: geo
      geo = geometry(a_star)
      state = case1_state(params, geo, x_of_v(geo, v))
   end function md_curve_state

   !> x from v: c* - a* = (1/2 - a*) e^v, 1/2 - c* = -(1/2 - a*) expm1(v), then as x_of_gap.
   pure function x_of_v(geo, v) result(x)
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: v
      real(wp) :: x
      real(wp) :: gap, top, rm1
      if (v >= 0.0_wp) then
         x = x_limit
         return
      end if
      gap = (0.5_wp - geo%a_star)*exp(v)
      if (v > -1.0e-5_wp) then                        ! 1 - e^v by its series
         top = (0.5_wp - geo%a_star)*(-v)*(1.0_wp + v*(0.5_wp + v/6.0_wp))
      else
         top = (0.5_wp - geo%a_star)*(1.0_wp - exp(v))
      end if
      rm1 = sin(pi*gap)/(geo%a*sin(pi*top))
      if (rm1 >= 1.0e-150_wp .and. rm1 <= 1.0e150_wp) then      ! one logarithm: no overflow
         x = min(x_limit, 0.5_wp*log(rm1*(rm1 + 2.0_wp)))
      else
         x = min(x_limit, 0.5_wp*(log(rm1) + log(rm1 + 2.0_wp)))
      end if
   end function x_of_v

   ! ------------------------------------------------------------ the solver

   !> Validate, treat the special cases, then find the case-1 roots (all, or only the
   !> first) and add the case-2 state.
   pure subroutine solve(params, a_star, first_only, opts, nres, states, n_states, status, &
         errmsg)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      logical, intent(in) :: first_only
      type(md_options), intent(in) :: opts
      integer, intent(inout) :: nres
      type(state_type), intent(inout) :: states(:)
      integer, intent(out) :: n_states, status
      character(len=*), intent(inout), optional :: errmsg
      type(md_geometry) :: geo
      real(wp) :: xr(max_roots)
      integer :: n_found, i

      n_states = 0
      call check_range("a_star", a_star, 0.0_wp, 0.5_wp, "[0, 1/2]", status, errmsg)
      if (status /= wa_ok) return
      if (a_star == 0.0_wp) then
         call set_error(wa_no_solution, "md: a_star = 0 is no contact; MD equilibria "// &
            "exist for 0 < a_star <= 1/2", status, errmsg)
         return
      end if
      if (a_star < a_star_min) then
         call set_error(wa_numerical_error, "md: a_star below 1e-100 is not resolved in "// &
            "double precision", status, errmsg)
         return
      end if
      geo = geometry(a_star)
      call add_scan_limits(geo)
      if (a_star == 0.5_wp .or. params%sigma0 == 0.0_wp) then
         n_states = 1
         states(1) = case2_state(params, geo)
         return
      end if
      call find_roots(params, geo, opts, nres, first_only, xr, n_found, status, errmsg)
      if (status /= wa_ok) return
      if (n_found > max_roots) then
         call set_error(wa_numerical_error, "md: more case-1 roots at one a_star than "// &
            "the solver keeps (8)", status, errmsg)
         return
      end if
      do i = 1, min(n_found, size(states))
         states(i) = case1_state(params, geo, xr(i))
      end do
      n_states = n_found
      if (first_only .and. n_found > 0) return
      if (geo%opening_top <= params%dcod) then
         n_states = n_states + 1
         if (n_states <= size(states)) states(n_states) = case2_state(params, geo)
      else if (n_found == 0) then
         call set_error(wa_no_solution, "md: no case-1 root, and case 2 fails: the "// &
            "opening at x = L/2 exceeds Dcod", status, errmsg)
      end if
   end subroutine solve

   !> Roots of F(x) = opening - Dcod, increasing: a scan from below the first root
   !> (F -> -Dcod as x -> -inf) to x_mono, each sign change refined by Brent, hidden
   !> pairs looked for at sampled extrema; then the monotone stretch up to c* = 1/2.
   pure subroutine find_roots(params, geo, opts, nres, first_only, xr, n_found, status, &
         errmsg)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      type(md_options), intent(in) :: opts
      integer, intent(inout) :: nres
      logical, intent(in) :: first_only
      real(wp), intent(out) :: xr(:)
      integer, intent(out) :: n_found, status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: xs(3), fs(3)
      integer :: n_pts

      xs = 0.0_wp
      fs = 0.0_wp
      n_found = 0
      status = wa_ok
      ! the opening is below opening_top + Sigma0 artanh(q) (Psi_c <= 0, Phi <= 1)
      if (params%dcod > geo%opening_top + params%sigma0*artanh_of(geo%q, geo%a**2)) return
      call scan_start(params, geo, opts, nres, xs(3), fs(3), status, errmsg)
      if (status /= wa_ok) return
      n_pts = 1
      do while (xs(3) < geo%x_mono .and. n_pts < max_scan_points)
         xs(1:2) = xs(2:3)
         fs(1:2) = fs(2:3)
         xs(3) = min(xs(2) + scan_step, geo%x_mono)
         nres = nres + 1
         fs(3) = residual(params, geo, xs(3), opts)
         n_pts = n_pts + 1
         if ((fs(2) < 0.0_wp) .neqv. (fs(3) < 0.0_wp)) then
            call add_root(params, geo, opts, nres, xs(2), fs(2), xs(3), fs(3), xr, n_found, &
               status, errmsg)
         else if (n_pts >= 3) then
            call hidden_pair(params, geo, opts, nres, xs, fs, xr, n_found, status, errmsg)
         end if
         if (status /= wa_ok .or. (first_only .and. n_found > 0)) return
      end do
      if (.not. (xs(3) >= geo%x_mono)) then
         call set_error(wa_numerical_error, "md: the root scan did not reach its end", &
            status, errmsg)
         return
      end if
      call top_root(params, geo, opts, nres, xs(3), fs(3), xr, n_found, status, errmsg)
   end subroutine find_roots

   !> A point x_lo with F(x_lo) < 0 just below the first root, placed by the small-zone
   !> expansion F ~ (Sigma0 A q/pi) s^2 + (2/3) A^2 q^3 s^3 - Dcod.
   pure subroutine scan_start(params, geo, opts, nres, x_lo, f_lo, status, errmsg)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      type(md_options), intent(in) :: opts
      integer, intent(inout) :: nres
      real(wp), intent(out) :: x_lo, f_lo
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: log_s_est
      integer :: i

      ! in logarithms: the estimate underflows where the zone is tiny (large mu, small a*)
      log_s_est = min(0.0_wp, &
         0.5_wp*(log(pi) + log(params%dcod) - log(params%sigma0) - log(geo%a) - log(geo%q)), &
         (log(1.5_wp) + log(params%dcod) - 2.0_wp*log(geo%a) - 3.0_wp*log(geo%q))/3.0_wp)
      x_lo = min(log_s_est - 1.5_wp, geo%x_mono - scan_step)
      if (.not. (x_lo > -650.0_wp)) then
         call set_error(wa_numerical_error, "md: the Dugdale zone at this (alpha, mu, "// &
            "a_star) is below the resolution of double precision", status, errmsg)
         return
      end if
      do i = 1, 40
         nres = nres + 1
         f_lo = residual(params, geo, x_lo, opts)
         if (f_lo < 0.0_wp) then
            status = wa_ok
            return
         end if
         x_lo = x_lo - 3.0_wp
         if (x_lo < -650.0_wp) exit
      end do
      call set_error(wa_not_converged, "md: the opening stays above Dcod as the zone "// &
         "shrinks; no bracket for the first case-1 root", status, errmsg)
   end subroutine scan_start

   !> Beyond x_mono: a root iff F(x_mono) and F(+inf) = opening_top - Dcod differ in sign.
   !> If even at x_top (where c* rounds to 1/2) F keeps its sign, the root is c* = 1/2.
   pure subroutine top_root(params, geo, opts, nres, x_b, f_b, xr, n_found, status, errmsg)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      type(md_options), intent(in) :: opts
      integer, intent(inout) :: nres
      real(wp), intent(in) :: x_b, f_b
      real(wp), intent(inout) :: xr(:)
      integer, intent(inout) :: n_found
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: f_hi

      status = wa_ok
      if ((f_b < 0.0_wp) .eqv. (geo%opening_top - params%dcod < 0.0_wp)) return
      nres = nres + 1
      f_hi = residual(params, geo, geo%x_top, opts)
      if ((f_b < 0.0_wp) .neqv. (f_hi < 0.0_wp)) then
         call add_root(params, geo, opts, nres, x_b, f_b, geo%x_top, f_hi, xr, n_found, &
            status, errmsg)
      else
         call store(xr, n_found, geo%x_top)
      end if
   end subroutine top_root

   !> Refine a sign change of F on [x1, x2] with Brent's method and store the root.
   pure subroutine add_root(params, geo, opts, nres, x1, f1, x2, f2, xr, n_found, status, &
         errmsg)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      type(md_options), intent(in) :: opts
      integer, intent(inout) :: nres
      real(wp), intent(in) :: x1, f1, x2, f2
      real(wp), intent(inout) :: xr(:)
      integer, intent(inout) :: n_found
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(brent_type) :: solver
      real(wp) :: x
      logical :: done
      integer :: iter

      call brent_init(solver, x1, f1, x2, f2, opts%xtol)
      do iter = 1, max_iterations
         call brent_propose(solver, x, done)
         if (done) exit
         nres = nres + 1
         call brent_accept(solver, residual(params, geo, x, opts))
      end do
      if (.not. done) then
         call set_error(wa_not_converged, "md: Brent's iteration for a case-1 root of "// &
            "(2.27b) did not converge", status, errmsg)
         return
      end if
      status = wa_ok
      call store(xr, n_found, solver%b)
   end subroutine add_root

   !> Two roots between samples: at a sampled extremum xs(2) of one sign that may reach
   !> 0 (is_extremum), search the extremum by golden sections until F changes sign there,
   !> then refine both roots.
   pure subroutine hidden_pair(params, geo, opts, nres, xs, fs, xr, n_found, status, &
         errmsg)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      type(md_options), intent(in) :: opts
      integer, intent(inout) :: nres
      real(wp), intent(in) :: xs(3), fs(3)
      real(wp), intent(inout) :: xr(:)
      integer, intent(inout) :: n_found
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: xm, fm
      logical :: found

      status = wa_ok
      if (.not. is_extremum(fs)) return
      call probe_extremum(params, geo, opts, nres, xs, fs, found, xm, fm)
      if (.not. found) return
      call add_root(params, geo, opts, nres, xs(1), fs(1), xm, fm, xr, n_found, status, errmsg)
      if (status /= wa_ok) return
      call add_root(params, geo, opts, nres, xm, fm, xs(3), fs(3), xr, n_found, status, errmsg)
   end subroutine hidden_pair

   !> True where fs(2) is an extremum of one-signed samples that may hide two roots: the
   !> extremum could reach 0 if F went on beyond it by twice the larger of the rises seen
   !> between the samples (a kinked peak with straight flanks needs once).
   pure logical function is_extremum(fs)
      real(wp), intent(in) :: fs(3)
      real(wp) :: g(3)
      g = fs
      if (fs(2) >= 0.0_wp) g = -fs
      is_extremum = .false.
      if (any(g >= 0.0_wp) .or. g(2) < g(1) .or. g(2) < g(3)) return
      is_extremum = g(2) + 2.0_wp*max(g(2) - g(1), g(2) - g(3)) >= 0.0_wp
   end function is_extremum

   !> Golden-section search for the extremum of F between xs(1) and xs(3); found when F
   !> changes sign at xm, given up when is_extremum says it cannot (or the bracket is
   !> below 1e-10: a double root, which counts as none).
   pure subroutine probe_extremum(params, geo, opts, nres, xs, fs, found, xm, fm)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      type(md_options), intent(in) :: opts
      integer, intent(inout) :: nres
      real(wp), intent(in) :: xs(3), fs(3)
      logical, intent(out) :: found
      real(wp), intent(out) :: xm, fm
      real(wp) :: x(3), f(3), xn, fn, sgn
      integer :: iter

      x = xs
      f = fs
      sgn = merge(-1.0_wp, 1.0_wp, fs(2) >= 0.0_wp)   ! maximise sgn*F
      found = .false.
      xm = x(2); fm = f(2)
      do iter = 1, max_iterations
         if (x(3) - x(1) <= 1.0e-10_wp*max(1.0_wp, abs(x(2)))) return
         if (.not. is_extremum(f)) return
         if (x(3) - x(2) > x(2) - x(1)) then
            xn = x(2) + golden*(x(3) - x(2))
         else
            xn = x(2) - golden*(x(2) - x(1))
         end if
         nres = nres + 1
         fn = residual(params, geo, xn, opts)
         xm = xn; fm = fn
         found = (fn < 0.0_wp) .neqv. (f(2) < 0.0_wp)
         if (found) return
         call golden_update(x, f, xn, fn, sgn)
      end do
   end subroutine probe_extremum

   !> Keep the triple around the largest sgn*F after a new point (xn, fn).
   pure subroutine golden_update(x, f, xn, fn, sgn)
      real(wp), intent(inout) :: x(3), f(3)
      real(wp), intent(in) :: xn, fn, sgn
      if (sgn*fn >= sgn*f(2)) then
         if (xn > x(2)) then
            x(1) = x(2); f(1) = f(2)
         else
            x(3) = x(2); f(3) = f(2)
         end if
         x(2) = xn; f(2) = fn
      else if (xn > x(2)) then
         x(3) = xn; f(3) = fn
      else
         x(1) = xn; f(1) = fn
      end if
   end subroutine golden_update

   !> Append a root (counted even where xr is full).
   pure subroutine store(xr, n_found, x)
      real(wp), intent(inout) :: xr(:)
      integer, intent(inout) :: n_found
      real(wp), intent(in) :: x
      n_found = n_found + 1
      if (n_found <= size(xr)) xr(n_found) = x
   end subroutine store


   ! ------------------------------------------------------------ the equations

   !> F(x) = opening - Dcod, the residual of (2.27b), with Psi_c by opts%psi_method
   !> (callers count the evaluations).
   pure function residual(params, geo, x, opts) result(f)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      type(md_options), intent(in) :: opts
      real(wp) :: f
      if (opts%psi_method == md_psi_rules) then
         f = opening(params, geo, x) - params%dcod
      else
         f = opening_alternative(params, geo, x, opts) - params%dcod
      end if
   end function residual

   !> The opening as `opening`, with Psi_c by a method of md_options other than the default.
   pure function opening_alternative(params, geo, x, opts) result(delta)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      type(md_options), intent(in) :: opts
      real(wp) :: delta
      type(md_zone) :: z
      real(wp) :: k
      if (x >= x_limit) then
         delta = top_opening(geo%a, geo%q)
         return
      end if
      z = zone_at(geo, x)
      k = md_psi_k_by(opts%psi_method, z, opts%gauss_rule, opts%psi_rtol)
      delta = geo%a**2*excess(z%k, z%omk2, z%chi2) &
         + params%sigma0*(dugdale_fraction(geo, x)*z%chi2 - (2.0_wp/pi)*geo%a*geo%q*z%sn**2*k)
   end function opening_alternative

   !> chi_1 C - P* chi_2 + Sigma0 Psi_c   (2.27b), as the Westergaard part
   !> A^2 (k/(1-k^2) - artanh k) plus Sigma0 times the Dugdale part Phi chi_2 + Psi_c.
   pure function opening(params, geo, x) result(delta)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      real(wp) :: delta
      type(md_zone) :: z
      if (x >= x_limit) then
         delta = top_opening(geo%a, geo%q)
         return
      end if
      z = zone_at(geo, x)
      delta = geo%a**2*excess(z%k, z%omk2, z%chi2) &
         + params%sigma0*(dugdale_fraction(geo, x)*z%chi2 + psi_c(geo, z))
   end function opening

   !> 1 - (2/pi) arcsin(cos(pi c*)/cos(pi a*)) = (2/pi) atan(A T)   (2.27a)
   pure function dugdale_fraction(geo, x) result(phi)
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      real(wp) :: phi
      phi = (2.0_wp/pi)*atan(geo%a*exp(min(x, x_limit)))
   end function dugdale_fraction

   !> k/(1-k^2) - artanh k = sum_{j>=1} 2j/(2j+1) k^(2j+1), without cancellation:
   !> k^3 (1/(1-k^2) - sum_j k^(2j)/(2j+3)) for k < 1/4.
   pure function excess(k, omk2, chi2) result(e)
      real(wp), intent(in) :: k, omk2, chi2
      real(wp) :: e
      real(wp) :: k2, series
      integer :: j
      if (k >= 0.25_wp) then
         e = k/omk2 - chi2
         return
      end if
      k2 = k*k
      series = 1.0_wp/29.0_wp
      do j = 12, 0, -1
         series = 1.0_wp/real(2*j + 3, wp) + k2*series
      end do
      e = k*k2*(1.0_wp/omk2 - series)
   end function excess

   !> artanh(k) = (1/2) ln((1+k)/(1-k)) from k and 1-k^2, accurate at both ends.
   pure function artanh_of(k, omk2) result(y)
      real(wp), intent(in) :: k, omk2
      real(wp) :: y
      y = 0.5_wp*log1p(2.0_wp*k*(1.0_wp + k)/omk2)
   end function artanh_of

   !> q - A^2 artanh(q): the opening at x = L/2 with c* = 1/2.
   pure function top_opening(a, q) result(delta)
      real(wp), intent(in) :: a, q
      real(wp) :: delta
      delta = a**2*excess(q, a**2, artanh_of(q, a**2))
   end function top_opening

   !> Psi_c = -(2 A q sin^2 s/pi) K   (2.27d)
   pure function psi_c(geo, z) result(psi)
      type(md_geometry), intent(in) :: geo
      type(md_zone), intent(in) :: z
      real(wp) :: psi
      psi = -(2.0_wp/pi)*geo%a*geo%q*z%sn**2*md_psi_k(z)
   end function psi_c


   ! ------------------------------------------------------------ geometry and states

   !> A, q, the case-2 opening and the scan limits for one a*.
   pure function geometry(a_star) result(geo)
      real(wp), intent(in) :: a_star
      type(md_geometry) :: geo
      geo%a_star = a_star
      call sincos_pi(a_star, geo%a, geo%q)
   end function geometry

   !> The fields of geo that only the root scan of `solve` needs.
   pure subroutine add_scan_limits(geo)
      type(md_geometry), intent(inout) :: geo
      real(wp) :: tan_a
      geo%opening_top = top_opening(geo%a, geo%q)
      tan_a = geo%a/geo%q
      ! 1/2 - c* ~ 1/(pi tan(pi a*) R): below 0.01 and 0.02 (1/2 - a*) beyond x_mono,
      ! below 2^-56 at x_top
      geo%x_mono = log(max(50.0_wp, 32.0_wp/tan_a))
      geo%x_top = min(x_limit, max(geo%x_mono + 1.0_wp, log(2.0_wp**56/(pi*tan_a))))
   end subroutine add_scan_limits

   !> T = e^x, R, sin s, cos s, k = q sin s, 1 - k^2 = cos^2 s + A^2 sin^2 s, artanh k.
   pure function zone_at(geo, x) result(z)
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      type(md_zone) :: z
      z%t = exp(min(x, x_limit))
      z%r = sqrt(1.0_wp + z%t**2)
      z%sn = z%t/z%r
      z%cs = 1.0_wp/z%r
      z%k = geo%q*z%sn
      z%omk2 = z%cs**2 + (geo%a*z%sn)**2
      z%chi2 = artanh_of(z%k, z%omk2)
   end function zone_at

   !> c* - a* from x: tan(pi (c*-a*)) = A q T^2/(R+1) / (q^2 + A^2 R)
   pure function gap_of_x(geo, x) result(gap)
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      real(wp) :: gap
      type(md_zone) :: z
      z = zone_at(geo, x)
      gap = atan2(geo%a*geo%q*z%t*(z%t/(z%r + 1.0_wp)), geo%q**2 + geo%a**2*z%r)/pi
      gap = min(gap, 0.5_wp - geo%a_star)
   end function gap_of_x

   !> x = ln T from c* - a*: R - 1 = sin(pi gap)/(A cos(pi c*)), T^2 = (R-1)(R+1).
   pure function x_of_gap(geo, gap) result(x)
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: gap
      real(wp) :: x
      real(wp) :: rm1, cos_c
      cos_c = sin(pi*((0.5_wp - geo%a_star) - gap))
      if (gap <= 0.0_wp) then
         x = -huge(x)
      else if (cos_c <= 0.0_wp) then
         x = x_limit
      else
         rm1 = sin(pi*gap)/(geo%a*cos_c)
         x = 0.5_wp*(log(rm1) + log(rm1 + 2.0_wp))
      end if
   end function x_of_gap

   !> 0 < a* < 1/2 and 0 <= gap <= 1/2 - a*.
   pure logical function valid_zone(a_star, gap)
      real(wp), intent(in) :: a_star, gap
      valid_zone = a_star > 0.0_wp .and. a_star < 0.5_wp .and. gap >= 0.0_wp &
         .and. gap <= 0.5_wp - a_star
   end function valid_zone

   !> Case-1 state at x: c* - a* from gap_of_x, P* from (2.27a).
   pure function case1_state(params, geo, x) result(state)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      type(state_type) :: state
      state%a_star = geo%a_star
      state%gap_width = gap_of_x(geo, x)
      ! case 1 has c* < 1/2 even where c* rounds to 1/2 (1/2 - c* below 2^-54; c* - a*
      ! keeps its full accuracy in gap_width)
      state%c_star = min(nearest(0.5_wp, -1.0_wp), geo%a_star + state%gap_width)
      state%p_star = case1_load(params, geo, x)
      state%zone_case = zone_inside
   end function case1_state

   !> P* of the case-1 state at x: A^2 - Sigma0 Phi   (2.27a)
   pure real(wp) function case1_load(params, geo, x)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      case1_load = geo%a**2 - params%sigma0*dugdale_fraction(geo, x)
   end function case1_load

   !> c* = 1/2, P* = A^2 - Sigma0 (extension); at a* = 1/2 full contact at P* = 1 - Sigma0.
   pure function case2_state(params, geo) result(state)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      type(state_type) :: state
      state%a_star = geo%a_star
      state%c_star = 0.5_wp
      state%gap_width = 0.5_wp - geo%a_star
      state%p_star = geo%a**2 - params%sigma0
      state%zone_case = zone_whole_period
      if (geo%a_star == 0.5_wp) state%zone_case = zone_full_contact
   end function case2_state

end module wa_md
