!> One entry point per question for every model, selected by its integer constant
!> (model_westergaard, model_jkr, model_dw, model_md): the principal equilibrium and all
!> equilibria at a given a*. Westergaard and JKR have no cohesive zone: their single
!> state has c* = a*, the closed-form load, zone case 1 (3 at a* = 1/2).
!> Shared by the C interface, the Python facade and the command-line driver.
module wa_models
   use wa_kinds, only: wp
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use wa_status, only: wa_ok, wa_invalid_argument, wa_no_solution, wa_capacity_too_small, &
      wa_numerical_error, set_error
   use wa_validate, only: check_range
   use wa_text, only: real_text, int_text
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside, zone_full_contact, model_westergaard, &
      model_jkr, model_dw, model_md
   use wa_kernels, only: westergaard_load, jkr_load
   use wa_dw, only: dw_equilibrium, dw_roots
   use wa_md, only: md_equilibrium, md_roots
   use wa_md_nocontact, only: md_no_contact_state
   use wa_separation, only: westergaard_mean_gap, jkr_mean_gap, state_profile
   implicit none
   private

   public :: check_model, model_equilibrium, model_roots, model_state, model_profile

   !> The most states one (alpha, mu, a*) can have in any model (DW's root scan keeps at
   !> most 48); internal callers size their buffers with it.
   integer, parameter, public :: max_model_roots = 48

   !> How close in c* (absolute) a state at a* must be to the c* that model_state asks for.
   real(wp), parameter, public :: state_c_tolerance = 1.0e-6_wp

contains

   !> status = wa_ok if `model` is one of the four model constants, else
   !> wa_invalid_argument with a message listing the valid values.
   pure subroutine check_model(model, status, errmsg)
      !> Model constant to check
      integer, intent(in) :: model
      !> wa_ok or wa_invalid_argument
      integer, intent(out) :: status
      !> Receives the reason on failure
      character(len=*), intent(inout), optional :: errmsg

      select case (model)
      case (model_westergaard, model_jkr, model_dw, model_md)
         status = wa_ok
      case default
         call set_error(wa_invalid_argument, "model = "//int_text(model)// &
            " is not one of 0 (westergaard), 1 (jkr), 2 (dw), 3 (md)", status, errmsg)
      end select
   end subroutine check_model

   !> Principal equilibrium of `model` at a*: for DW and MD the
   !> case-1 state with the smallest c*, else the case-2 state.
   pure subroutine model_equilibrium(model, params, a_star, state, status, errmsg)
      !> Model constant (model_westergaard, model_jkr, model_dw, model_md)
      integer, intent(in) :: model
      !> Validated parameters (new_params)
      type(params_type), intent(in) :: params
      !> Contact half-width over the period, in [0, 1/2]
      real(wp), intent(in) :: a_star
      !> The principal state
      type(state_type), intent(out) :: state
      !> wa_ok or the failure's status code
      integer, intent(out) :: status
      !> Receives the reason on failure
      character(len=*), intent(inout), optional :: errmsg

      call check_model(model, status, errmsg)
      if (status /= wa_ok) return
      select case (model)
      case (model_dw)
         call dw_equilibrium(params, a_star, state, status, errmsg)
      case (model_md)
         call md_equilibrium(params, a_star, state, status, errmsg)
      case default
         call closed_form_state(model, params, a_star, state, status, errmsg)
      end select
   end subroutine model_equilibrium

   !> Every equilibrium of `model` at a* (one for Westergaard and JKR). n_roots is the
   !> total; if it exceeds size(states), the first size(states) are stored and status
   !> is wa_capacity_too_small.
   pure subroutine model_roots(model, params, a_star, states, n_roots, status, errmsg)
      !> Model constant (model_westergaard, model_jkr, model_dw, model_md)
      integer, intent(in) :: model
      !> Validated parameters (new_params)
      type(params_type), intent(in) :: params
      !> Contact half-width over the period, in [0, 1/2]
      real(wp), intent(in) :: a_star
      !> Receives the states, by increasing c* (case 1), then case 2
      type(state_type), intent(inout) :: states(:)
      !> Number of equilibria found (may exceed size(states))
      integer, intent(out) :: n_roots
      !> wa_ok or the failure's status code
      integer, intent(out) :: status
      !> Receives the reason on failure
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: state

      n_roots = 0
      call check_model(model, status, errmsg)
      if (status /= wa_ok) return
      select case (model)
      case (model_dw)
         call dw_roots(params, a_star, states, n_roots, status, errmsg)
      case (model_md)
         call md_roots(params, a_star, states, n_roots, status, errmsg)
      case default
         call closed_form_state(model, params, a_star, state, status, errmsg)
         if (status /= wa_ok) return
         n_roots = 1
         if (size(states) >= 1) then
            states(1) = state
         else
            call set_error(wa_capacity_too_small, "states: capacity too small for all roots", &
               status, errmsg)
         end if
      end select
   end subroutine model_roots

   !> The solved state of `model` at a* that `c_star` identifies (for its profile,
   !> wa_separation::state_profile): among the roots at a* (model_roots) the one with the
   !> nearest c*, wa_no_solution when none lies within state_c_tolerance (1e-6) of c_star
   !> (Westergaard, JKR: c* = a*). MD at a* = 0: the no-contact state with zone half-width
   !> c_star < 1/2 (md_no_contact_state; at c* = 1/2 the crest gap is free: no single
   !> state). Without c_star: the principal state (model_equilibrium; MD at a* = 0 needs
   !> c_star). wa_no_solution also for JKR at a* = 1/2 (full contact at any load) and DW at
   !> a* = 0 (no contact: DW has no states without contact).
   pure subroutine model_state(model, params, a_star, state, status, errmsg, c_star)
      !> Model constant (model_westergaard, model_jkr, model_dw, model_md)
      integer, intent(in) :: model
      !> Validated parameters (new_params)
      type(params_type), intent(in) :: params
      !> Contact half-width over the period, in [0, 1/2]
      real(wp), intent(in) :: a_star
      !> The state
      type(state_type), intent(out) :: state
      !> wa_ok or the failure's status code
      integer, intent(out) :: status
      !> Receives the reason on failure
      character(len=*), intent(inout), optional :: errmsg
      !> Interaction-zone half-width of the state, in [0, 1/2] (default: the principal state)
      real(wp), intent(in), optional :: c_star
      type(state_type) :: states(max_model_roots)
      integer :: n, k, best

      call check_model(model, status, errmsg)
      if (status /= wa_ok) return
      call check_range("a_star", a_star, 0.0_wp, 0.5_wp, "[0, 1/2]", status, errmsg)
      if (status /= wa_ok) return
      if (present(c_star)) then
         call check_range("c_star", c_star, 0.0_wp, 0.5_wp, "[0, 1/2]", status, errmsg)
         if (status /= wa_ok) return
      end if
      if (model == model_jkr .and. a_star == 0.5_wp) then
         call set_error(wa_no_solution, "jkr: full contact (a_star = 1/2) holds at any "// &
            "load: it is not one state", status, errmsg)
         return
      end if
      if (model == model_dw .and. a_star == 0.0_wp) then
         call set_error(wa_no_solution, "dw: a_star = 0 is no contact, and DW has no "// &
            "states without contact (give 0 < a_star <= 1/2)", status, errmsg)
         return
      end if
      if (model == model_md .and. a_star == 0.0_wp) then
         if (.not. present(c_star)) then
            call set_error(wa_invalid_argument, "c_star: needed for md at a_star = 0 (the "// &
               "no-contact states are identified by their zone half-width c*)", status, errmsg)
         else if (c_star == 0.5_wp) then
            call set_error(wa_no_solution, "md: at a_star = 0 and c_star = 1/2 the zone "// &
               "covers the period and the crest gap is free: not one state (give c_star "// &
               "< 1/2)", status, errmsg)
         else
            call md_no_contact_state(params, c_star, state, status, errmsg)
         end if
         return
      end if
      if (.not. present(c_star)) then
         call model_equilibrium(model, params, a_star, state, status, errmsg)
         return
      end if
      call model_roots(model, params, a_star, states, n, status, errmsg)
      if (status /= wa_ok) return
      best = 0
      do k = 1, n
         if (best == 0) then
            best = k
         else if (abs(states(k)%c_star - c_star) < abs(states(best)%c_star - c_star)) then
            best = k
         end if
      end do
      if (best == 0) then
         call set_error(wa_no_solution, "no equilibrium at this a_star", status, errmsg)
         return
      end if
      if (abs(states(best)%c_star - c_star) > state_c_tolerance) then
         call set_error(wa_no_solution, "c_star = "//real_text(c_star)//": no state at "// &
            "a_star = "//real_text(a_star)//" has c* within 1e-6 (of its "// &
            int_text(n)//" states the nearest has c* = "//real_text(states(best)%c_star)//")", &
            status, errmsg)
         return
      end if
      state = states(best)
   end subroutine model_state

   !> Traction p/p* and gap h/Delta at every x_star of the state model_state identifies
   !> (state receives it). Every gap is finite and >= 0, every traction finite except
   !> JKR's -Infinity exactly at |x*| = a* (folded into [0, 1/2] as |x* - anint(x*)|):
   !> anything else (an underflow at extreme a*) is wa_numerical_error, never returned.
   !> traction and gap must have the size of x_star; on failure they are 0.
   pure subroutine model_profile(model, params, a_star, x_star, traction, gap, state, &
         status, errmsg, c_star)
      !> Model constant (model_westergaard, model_jkr, model_dw, model_md)
      integer, intent(in) :: model
      !> Validated parameters (new_params)
      type(params_type), intent(in) :: params
      !> Contact half-width over the period, in [0, 1/2]
      real(wp), intent(in) :: a_star
      !> The points x* (any finite values: period 1, crest at 0)
      real(wp), intent(in) :: x_star(:)
      !> Receive p/p* and h/Delta at each x_star
      real(wp), intent(out) :: traction(:), gap(:)
      !> The state
      type(state_type), intent(out) :: state
      !> wa_ok or the failure's status code
      integer, intent(out) :: status
      !> Receives the reason on failure
      character(len=*), intent(inout), optional :: errmsg
      !> Interaction-zone half-width of the state, in [0, 1/2] (default: the principal state)
      real(wp), intent(in), optional :: c_star
      integer :: i

      traction = 0.0_wp
      gap = 0.0_wp
      call model_state(model, params, a_star, state, status, errmsg, c_star)
      if (status /= wa_ok) return
      call state_profile(model, params, state, x_star, traction, gap, status, errmsg)
      if (status /= wa_ok) return
      do i = 1, size(x_star)
         if (ieee_is_finite(gap(i)) .and. gap(i) >= 0.0_wp) then
            if (ieee_is_finite(traction(i))) cycle
            if (model == model_jkr .and. traction(i) < 0.0_wp .and. &
                  abs(x_star(i) - anint(x_star(i))) == state%a_star) cycle
         end if
         call set_error(wa_numerical_error, "profile: traction or gap not finite (or gap "// &
            "< 0) at point "//int_text(i)//" (an underflow at this a_star)", status, errmsg)
         traction = 0.0_wp
         gap = 0.0_wp
         return
      end do
   end subroutine model_profile

   !> Westergaard (3.1) or JKR (3.4) state: c* = a*, zone case 1, or 3 at a* = 1/2
   !> (JKR: P* = -Infinity there, full contact never releases).
   pure subroutine closed_form_state(model, params, a_star, state, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      type(state_type), intent(out) :: state
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg

      call check_range("a_star", a_star, 0.0_wp, 0.5_wp, "[0, 1/2]", status, errmsg)
      if (status /= wa_ok) return
      state%a_star = a_star
      state%c_star = a_star
      state%gap_width = 0.0_wp
      if (model == model_jkr) then
         state%p_star = jkr_load(params%alpha, a_star)
         state%gbar = jkr_mean_gap(params%alpha, a_star)
      else
         state%p_star = westergaard_load(a_star)
         state%gbar = westergaard_mean_gap(a_star)
      end if
      state%zone_case = merge(zone_full_contact, zone_inside, a_star == 0.5_wp)
   end subroutine closed_form_state

end module wa_models
