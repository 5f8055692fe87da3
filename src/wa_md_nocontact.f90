!> The Maugis-Dugdale states without contact (zone case 0, a* = 0; doc/theory.md,
!> "Separation"): a cohesive zone |x*| < c* under the uniform traction -Sigma0, the load
!> P* = -2 Sigma0 c*, the crest gap
!>   H(c*) = h(0)/Delta = 2 Dcod - 2 C^2 + (Sigma0/pi) [Cl2(4 pi c*) - 2 Cl2(2 pi c*)]
!> (h(c*) = 2 Dcod, C = sin(pi c*)) and gbar = H + 1 + (2 Sigma0/pi) Cl2(2 pi c*); at c* = 1/2
!> the crest gap is free in [0, 2 Dcod - 2] (P* = -Sigma0) and is stored as gbar - 1.
!> The states exist where H >= 0; H decreases on (0, 1/3) and is convex on (1/4, 1/2), so
!> the family (from the first interaction at c* = 0 to where the crest closes and the
!> a* -> 0 end of the contact curve takes over) has at most two closures.
!> A model module beside wa_md (the contact states); the profiles and mean gap of these
!> states, and the closed form of H they use, are wa_separation's.
module wa_md_nocontact
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_invalid_argument, wa_no_solution, wa_not_converged, &
      wa_numerical_error, set_error
   use wa_validate, only: check_range
   use wa_params, only: params_type, check_params
   use wa_state, only: state_type, zone_no_contact
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_separation, only: no_contact_crest, no_contact_clausen
   implicit none
   private

   public :: md_no_contact_crest_gap, md_no_contact_state, md_no_contact_closures
   public :: md_no_contact_family

   integer, parameter :: max_iterations = 200

contains

   !> Crest gap h(0)/Delta of the no-contact MD state with zone half-width c* in [0, 1/2]:
   !>   2 Dcod - 2 C^2 + (Sigma0/pi) [Cl2(4 pi c*) - 2 Cl2(2 pi c*)]   (h(c*) = 2 Dcod).
   !> NaN outside [0, 1/2].
   elemental function md_no_contact_crest_gap(params, c_star) result(h)
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> Cohesive-zone half-width over the period, c* = c/L, in [0, 1/2] (NaN result outside)
      real(wp), intent(in) :: c_star
      real(wp) :: h
      if (.not. (c_star >= 0.0_wp .and. c_star <= 0.5_wp)) then
         h = ieee_value(h, ieee_quiet_nan)
         return
      end if
      h = no_contact_crest(params, c_star)
   end function md_no_contact_crest_gap

   !> The no-contact MD state (zone case 0, a* = 0) with cohesive half-width c* in
   !> [0, 1/2]: P* = -2 Sigma0 c*, gbar from the Clausen closed form. At c* = 1/2 the
   !> state is not fixed by c*: pass crest_gap in [0, 2 Dcod - 2] (then P* = -Sigma0,
   !> gbar = 1 + crest_gap). wa_no_solution where the crest gap would be negative
   !> (the surfaces would touch: a contact state) or mu = 0 (no cohesive zone).
   pure subroutine md_no_contact_state(params, c_star, state, status, errmsg, crest_gap)
      !> Validated dimensionless parameters alpha, mu (new_params), mu > 0
      type(params_type), intent(in) :: params
      !> Cohesive-zone half-width over the period, c* = c/L, in [0, 1/2]
      real(wp), intent(in) :: c_star
      !> The state: zone case 0 (zone_no_contact), a* = 0, c*, P* = -2 Sigma0 c*, gbar* =
      !> mean gap/Delta; on failure the default state_type (zeros, gbar = -1)
      type(state_type), intent(out) :: state
      !> wa_ok; wa_invalid_argument for bad params, c_star out of range, or crest_gap
      !> missing or out of range at c* = 1/2; wa_no_solution at mu = 0, where the crest gap
      !> would be negative, or at c* = 1/2 when Dcod < 1
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      !> Crest gap h(0)/Delta, in [0, 2 Dcod - 2]: needed at c* = 1/2 only (ignored
      !> elsewhere)
      real(wp), intent(in), optional :: crest_gap
      real(wp) :: h00

      call check_params(params, status, errmsg)
      if (status /= wa_ok) return
      call check_range("c_star", c_star, 0.0_wp, 0.5_wp, "[0, 1/2]", status, errmsg)
      if (status /= wa_ok) return
      if (params%sigma0 == 0.0_wp) then
         call set_error(wa_no_solution, "md: mu = 0 has no cohesive zone, hence no "// &
            "no-contact states", status, errmsg)
         return
      end if
      if (c_star == 0.5_wp) then
         if (.not. present(crest_gap)) then
            call set_error(wa_invalid_argument, "crest_gap: needed at c_star = 1/2 (the "// &
               "zone covers the period; the crest gap is free)", status, errmsg)
            return
         end if
         call check_range("crest_gap", crest_gap, 0.0_wp, max(0.0_wp, 2.0_wp*params%dcod - &
            2.0_wp), "[0, 2 Dcod - 2]", status, errmsg)
         if (status /= wa_ok) return
         if (params%dcod < 1.0_wp) then
            call set_error(wa_no_solution, "md: the zone cannot cover the period without "// &
               "contact when Dcod < 1", status, errmsg)
            return
         end if
         h00 = crest_gap
      else
         h00 = no_contact_crest(params, c_star)
         if (h00 < 0.0_wp) then
            call set_error(wa_no_solution, "md: no no-contact state at this c_star (the "// &
               "crest gap would be negative)", status, errmsg)
            return
         end if
      end if
      state%a_star = 0.0_wp
      state%c_star = c_star
      state%gap_width = c_star
      state%zone_case = zone_no_contact
      if (c_star == 0.5_wp) then
         state%p_star = -params%sigma0
         state%gbar = 1.0_wp + h00
      else
         state%p_star = 0.0_wp - 2.0_wp*params%sigma0*c_star     ! +0 at c* = 0
         state%gbar = h00 + 1.0_wp + (2.0_wp*params%sigma0/pi)*no_contact_clausen(c_star)
      end if
   end subroutine md_no_contact_state

   !> Where the no-contact states close (crest gap = 0, joining the a* -> 0 end of the
   !> contact curve). The crest gap H(c*) decreases on (0, 1/3) and is convex on (1/4, 1/2),
   !> so it has one minimum c_min in [1/3, 1/2) and at most two zeros: n_close of them are
   !> returned in c_close(1:n_close), increasing. stretch is true when Dcod >= 1: then the
   !> states with c* = 1/2 (crest gap in [0, 2 Dcod - 2], P* = -Sigma0) exist too.
   pure subroutine md_no_contact_closures(params, c_close, n_close, stretch, status, errmsg)
      !> Validated dimensionless parameters alpha, mu (new_params), mu > 0
      type(params_type), intent(in) :: params
      !> Receives the c* in (0, 1/2) where the crest gap closes, increasing, in
      !> c_close(1:n_close); the rest is 1/2 (on failure c_close(1:n_close) may hold an
      !> unconverged value)
      real(wp), intent(out) :: c_close(2)
      !> Number of closures, 0, 1 or 2; 0 for bad params or mu = 0 (on wa_not_converged:
      !> the closures attempted)
      integer, intent(out) :: n_close
      !> True when Dcod >= 1 (the states with c* = 1/2 exist); false for bad params or mu = 0
      logical, intent(out) :: stretch
      !> wa_ok; wa_invalid_argument for bad params; wa_no_solution at mu = 0;
      !> wa_not_converged where the minimum or a zero of the crest gap does not converge
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: c_min, h_min, h_top

      c_close = 0.5_wp
      n_close = 0
      stretch = .false.
      call check_params(params, status, errmsg)
      if (status /= wa_ok) return
      if (params%sigma0 == 0.0_wp) then
         call set_error(wa_no_solution, "md: mu = 0 has no cohesive zone, hence no "// &
            "no-contact states", status, errmsg)
         return
      end if
      stretch = params%dcod >= 1.0_wp
      call crest_minimum(params, c_min, status, errmsg)
      if (status /= wa_ok) return
      h_min = no_contact_crest(params, c_min)
      if (h_min >= 0.0_wp) return
      n_close = 1
      call crest_zero(params, 0.0_wp, c_min, c_close(1), status, errmsg)
      if (status /= wa_ok) return
      h_top = 2.0_wp*params%dcod - 2.0_wp
      if (h_top > 0.0_wp) then
         n_close = 2
         call crest_zero(params, c_min, 0.5_wp, c_close(2), status, errmsg)
      end if
   end subroutine md_no_contact_closures

   !> size(states) no-contact MD states along one piece of the family, in order along it.
   !> piece 1: from the first interaction (c* = 0, P* = 0, gbar = 1 + 2 Dcod) to where the
   !>   crest gap closes: at c_close(1), or, if the crest never closes for c* < 1/2, up
   !>   to c* = 1/2 and then along c* = 1/2 with the crest gap falling from 2 Dcod - 2 to 0.
   !> piece 2 (exists only when the crest gap closes at c_close(1) and reopens, Dcod > 1):
   !>   from the closure at c_close(2) up to c* = 1/2, then the crest gap from 2 Dcod - 2
   !>   to 0; n_states = 0 if it does not exist.
   !> The last state of a piece has crest gap 0 (it joins the a* -> 0 end of the contact
   !> curve at that c*). c* is sampled densely near c* = 0 (gbar ~ c* ln c* there).
   pure subroutine md_no_contact_family(params, piece, states, n_states, status, errmsg)
      !> Validated dimensionless parameters alpha, mu (new_params), mu > 0
      type(params_type), intent(in) :: params
      !> Which piece of the family: 1 from the first interaction, 2 from the second closure
      !> to c* = 1/2
      integer, intent(in) :: piece
      !> Receives the states in order along the piece (size(states) >= 3 of them); on
      !> failure the states up to the failing one may have been overwritten
      type(state_type), intent(inout) :: states(:)
      !> Number of states stored: size(states), or 0 when piece 2 does not exist or on failure
      integer, intent(out) :: n_states
      !> wa_ok (also when piece 2 does not exist); wa_invalid_argument for a bad piece,
      !> size(states) < 3 or bad params; wa_no_solution at mu = 0; wa_not_converged or
      !> wa_numerical_error where a closure or a state next to it cannot be resolved
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: c_close(2), c_lo, c_hi, t, h_top
      integer :: n_close, n, n_c, n_s, i
      logical :: stretch, with_stretch

      n_states = 0
      n = size(states)
      if (piece /= 1 .and. piece /= 2) then
         call set_error(wa_invalid_argument, "piece: must be 1 (from the first interaction) "// &
            "or 2 (the piece between the second closure and c_star = 1/2)", status, errmsg)
         return
      end if
      if (n < 3) then
         call set_error(wa_invalid_argument, "states: need room for at least 3 states", &
            status, errmsg)
         return
      end if
      call md_no_contact_closures(params, c_close, n_close, stretch, status, errmsg)
      if (status /= wa_ok) return
      h_top = 2.0_wp*params%dcod - 2.0_wp
      if (piece == 1) then
         c_lo = 0.0_wp
         with_stretch = n_close == 0
         c_hi = merge(0.5_wp, c_close(1), with_stretch)
      else
         if (n_close < 2) return
         c_lo = c_close(2)
         c_hi = 0.5_wp
         with_stretch = .true.
      end if
      n_s = 0
      if (with_stretch .and. h_top > 0.0_wp) n_s = max(1, n/4)
      n_c = n - n_s
      do i = 1, n_c
         t = real(i - 1, wp)/real(n_c - 1, wp)
         if (piece == 1) then
            call family_state(params, c_lo + (c_hi - c_lo)*t*t, h_top, states(i), status, errmsg)
         else
            call family_state(params, c_lo + (c_hi - c_lo)*t, h_top, states(i), status, errmsg)
         end if
         if (status /= wa_ok) return
      end do
      do i = 1, n_s
         call family_state(params, 0.5_wp, h_top, states(n_c + i), status, errmsg, &
            h_top*real(n_s - i, wp)/real(n_s, wp))
         if (status /= wa_ok) return
      end do
      n_states = n
   end subroutine md_no_contact_family

   ! ================================================================ internals

   !> One state of md_no_contact_family: at c (clamped to [0, 1/2]); at c = 1/2 with the
   !> crest gap `crest` (default h_top, where the c*-part meets the stretch).
   pure subroutine family_state(params, c, h_top, s, status, errmsg, crest)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: c, h_top
      type(state_type), intent(inout) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), intent(in), optional :: crest
      real(wp) :: cc
      cc = min(0.5_wp, max(0.0_wp, c))
      if (present(crest)) then
         call md_no_contact_state(params, cc, s, status, errmsg, crest)
      else if (cc == 0.5_wp) then
         call md_no_contact_state(params, cc, s, status, errmsg, max(0.0_wp, h_top))
      else
         call md_no_contact_state(params, cc, s, status, errmsg)
         ! at a closure round-off may leave the crest gap a hair below 0: try the
         ! neighbours within 4 eps, never past 1/2 (there the crest gap is the variable)
         if (status == wa_no_solution) then
            call md_no_contact_state(params, cc*(1.0_wp - 4.0_wp*epsilon(1.0_wp)), s, &
               status, errmsg)
            if (status /= wa_ok .and. cc*(1.0_wp + 4.0_wp*epsilon(1.0_wp)) < 0.5_wp) &
               call md_no_contact_state(params, cc*(1.0_wp + 4.0_wp*epsilon(1.0_wp)), s, &
               status, errmsg)
            if (status /= wa_ok) call set_error(wa_numerical_error, "md: the no-contact "// &
               "crest gap is negative to round-off next to where it closes (not resolved "// &
               "in double precision at this alpha, mu)", status, errmsg)
         end if
      end if
   end subroutine family_state

   !> dH/dc* = -2 pi sin(2 pi c*) - 4 Sigma0 ln(2 cos(pi c*))
   elemental function crest_slope(params, c_star) result(d)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: c_star
      real(wp) :: d
      d = -2.0_wp*pi*sin(2.0_wp*pi*c_star) - 4.0_wp*params%sigma0* &
         log(2.0_wp*sin(pi*(0.5_wp - c_star)))
   end function crest_slope

   !> The minimum of the crest gap: the zero of dH/dc* in [1/3, 1/2).
   pure subroutine crest_minimum(params, c_min, status, errmsg)
      type(params_type), intent(in) :: params
      real(wp), intent(out) :: c_min
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(brent_type) :: solver
      real(wp) :: x, hi
      logical :: done
      integer :: iter
      ! dH/dc* -> +inf as c* -> 1/2: walk up until it is positive
      hi = 0.5_wp - 1.0e-3_wp
      do iter = 1, 300
         if (crest_slope(params, hi) > 0.0_wp) exit
         hi = 0.5_wp - 0.5_wp*(0.5_wp - hi)
      end do
      call brent_init(solver, 1.0_wp/3.0_wp, crest_slope(params, 1.0_wp/3.0_wp), hi, &
         crest_slope(params, hi), 1.0e-16_wp)
      do iter = 1, max_iterations
         call brent_propose(solver, x, done)
         if (done) exit
         call brent_accept(solver, crest_slope(params, x))
      end do
      c_min = solver%b
      if (done) then
         status = wa_ok
      else
         call set_error(wa_not_converged, "md: the minimum of the no-contact crest gap "// &
            "did not converge", status, errmsg)
      end if
   end subroutine crest_minimum

   !> The zero of the crest gap between lo and hi (where it changes sign).
   pure subroutine crest_zero(params, lo, hi, c0, status, errmsg)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: lo, hi
      real(wp), intent(out) :: c0
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(brent_type) :: solver
      real(wp) :: x
      logical :: done
      integer :: iter
      call brent_init(solver, lo, no_contact_crest(params, lo), hi, no_contact_crest(params, hi), 1.0e-300_wp)
      do iter = 1, max_iterations
         call brent_propose(solver, x, done)
         if (done) exit
         call brent_accept(solver, no_contact_crest(params, x))
      end do
      ! the end of the final bracket where the crest gap is >= 0: the state there exists
      c0 = merge(solver%b, solver%c, solver%fb >= 0.0_wp)
      if (done) then
         status = wa_ok
      else
         call set_error(wa_not_converged, "md: the closure of the no-contact crest gap "// &
            "did not converge", status, errmsg)
      end if
   end subroutine crest_zero

end module wa_md_nocontact
