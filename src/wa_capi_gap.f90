!> display: none
!>
!> The C interface, gap (mean-gap) control: the gap-controlled path, the gap law and the
!> critical values under gap control (declarations in include/wavyadhesion.h; the
!> conventions in wa_capi). Each export is one call of its `*_core` routine.
module wa_capi_gap
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_associated, c_f_pointer
   use wa_status, only: wa_ok, wa_invalid_argument, wa_numerical_error, set_error
   use wa_params, only: params_type, new_params
   use wa_models, only: check_model
   use wa_validate, only: check_range
   use wa_gappath, only: gap_path_type, gap_path, gap_law
   use wa_gapcritical, only: gap_critical_type, gap_critical, gap_critical_values, &
      gap_critical_count
   use wa_capi_util, only: msg_len, copy_message, check_outputs, too_small, &
      internal_capacity, check_gbar_values, put_nan, put_int, put_nans, store_reals, &
      store_ints, store_scalar
   implicit none
   private

   public :: capi_gap_path, capi_gap_law, capi_gap_critical
   public :: gap_path_core, gap_law_core, gap_critical_core

contains

   !> int wa_gap_path(model, alpha, mu, capacity, stage[], event[], zone_case[], a_star[],
   !> c_star[], P_star[], gbar[], *n_events, *W_star, *W_fraction, *g_touch, message,
   !> message_capacity): the events of the gap-controlled approach (stage 1) and retraction
   !> (stage 2) (gap_path), the energy lost per cycle and the gbar* of the first
   !> interaction. When *n_events exceeds `capacity` the first `capacity` events are
   !> written (the three scalars too) and the status is WA_CAPACITY_TOO_SMALL. On any other
   !> failure *n_events = 0 and *W_star = *W_fraction = *g_touch = NaN (each not NULL).
   function capi_gap_path(model, alpha, mu, capacity, stage, event, zone_case, a_star, &
         c_star, p_star, gbar, n_events, w_star, w_fraction, g_touch, message, &
         message_capacity) result(status) bind(C, name="wa_gap_path")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter and the transition parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha, mu
      !> Length of the seven arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> int[capacity]: stage (WA_STAGE_APPROACH, WA_STAGE_RETRACTION), event code
      !> (WA_GAP_EVENT_*) and zone case of each event
      type(c_ptr), value, intent(in) :: stage, event, zone_case
      !> double[capacity]: a*, c*, P* and gbar* of each event
      type(c_ptr), value, intent(in) :: a_star, c_star, p_star, gbar
      !> int *: receives the number of events
      type(c_ptr), value, intent(in) :: n_events
      !> double *: receive W*, W*/(pi alpha^2/2) and the gbar* of the first interaction
      type(c_ptr), value, intent(in) :: w_star, w_fraction, g_touch
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = gap_path_core(model, alpha, mu, capacity, [stage, event, zone_case], &
         [a_star, c_star, p_star, gbar], n_events, [w_star, w_fraction, g_touch], message, &
         message_capacity)
   end function capi_gap_path

   !> int wa_gap_law(model, alpha, mu, n, gbar[], P_approach[], P_retract[],
   !> dPdg_approach[], dPdg_retract[], message, message_capacity): the gap law (gap_law)
   !> at n mean gaps. On any failure, when n > 0, every element of each output array that
   !> is not NULL is NaN.
   function capi_gap_law(model, alpha, mu, n, gbar, p_approach, p_retract, dpdg_approach, &
         dpdg_retract, message, message_capacity) result(status) bind(C, name="wa_gap_law")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter and the transition parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha, mu
      !> Number of mean gaps, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n
      !> const double[n]: mean gaps gbar*, each finite and >= 0
      type(c_ptr), value, intent(in) :: gbar
      !> double[n]: P* on approach and on retraction
      type(c_ptr), value, intent(in) :: p_approach, p_retract
      !> double[n]: dP*/dgbar* on approach and on retraction
      type(c_ptr), value, intent(in) :: dpdg_approach, dpdg_retract
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = gap_law_core(model, alpha, mu, n, gbar, [p_approach, p_retract, &
         dpdg_approach, dpdg_retract], message, message_capacity)
   end function capi_gap_law

   !> int wa_gap_critical(model, alpha, mu, values[WA_GAP_CRITICAL_COUNT], message,
   !> message_capacity): the critical values under gap control (gap_critical), in the
   !> order WA_GAP_CRITICAL_G_TOUCH ... WA_GAP_CRITICAL_G_INTERACTION_LOST. On any failure
   !> every element of values (when it is not NULL) is NaN.
   function capi_gap_critical(model, alpha, mu, values, message, message_capacity) &
         result(status) bind(C, name="wa_gap_critical")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter and the transition parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha, mu
      !> double[WA_GAP_CRITICAL_COUNT]: receives the values
      type(c_ptr), value, intent(in) :: values
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = gap_critical_core(model, alpha, mu, values, message, message_capacity)
   end function capi_gap_critical

   ! ---------------------------------------------------------------- cores

   !> Validate, follow the gap-controlled cycle, write min(n, capacity) events, n and the
   !> scalars. ints = [stage, event, zone_case], reals = [a_star, c_star, P_star, gbar],
   !> scalars = [W_star, W_fraction, g_touch].
   function gap_path_core(model, alpha, mu, capacity, ints, reals, n_events, scalars, &
         message, message_capacity) result(status)
      integer(c_int), intent(in) :: model, capacity, message_capacity
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: ints(3), reals(4), n_events, scalars(3), message
      integer(c_int) :: status
      integer(c_int), pointer :: n_out
      type(params_type) :: params
      type(gap_path_type) :: path
      integer :: stat, m, k
      character(len=msg_len) :: msg

      msg = ""
      call put_int(n_events, 0)
      do k = 1, 3
         call put_nan(scalars(k))
      end do
      call check_outputs("n_events", n_events, "capacity", capacity, [ints, reals], &
         "stage, event, zone_case, a_star, c_star, P_star and gbar", stat, msg)
      if (stat == wa_ok .and. .not. (c_associated(scalars(1)) .and. &
         c_associated(scalars(2)) .and. c_associated(scalars(3)))) &
         call set_error(wa_invalid_argument, "W_star, W_fraction and g_touch must not "// &
         "be NULL", stat, msg)
      if (stat == wa_ok) call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call gap_path(int(model), params, path, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) call check_gbar_values(path%gbar(1:path%n), stat, msg)
      if (stat == wa_ok) then
         m = min(path%n, int(capacity))
         call store_ints(ints(1), path%stage(1:m))
         call store_ints(ints(2), path%event(1:m))
         call store_ints(ints(3), path%zone_case(1:m))
         call store_reals(reals(1), path%a_star(1:m))
         call store_reals(reals(2), path%c_star(1:m))
         call store_reals(reals(3), path%p_star(1:m))
         call store_reals(reals(4), path%gbar(1:m))
         call c_f_pointer(n_events, n_out)
         n_out = int(path%n, c_int)
         call store_scalar(scalars(1), path%w_star)
         call store_scalar(scalars(2), path%w_fraction)
         call store_scalar(scalars(3), path%g_touch)
         if (path%n > capacity) call too_small("the gap path has", "events", path%n, &
            capacity, stat, msg)
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function gap_path_core

   !> Validate everything (every gbar first), then the gap law at n mean gaps (every
   !> element of the outputs NaN on any failure, when n > 0 and they are not NULL).
   !> outs = [P_approach, P_retract, dPdg_approach, dPdg_retract].
   function gap_law_core(model, alpha, mu, n, gbar, outs, message, message_capacity) &
         result(status)
      integer(c_int), intent(in) :: model, n, message_capacity
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: gbar, outs(4), message
      integer(c_int) :: status
      real(c_double), pointer :: g_in(:)
      real(c_double), allocatable :: res(:, :)
      type(params_type) :: params
      integer :: stat, k
      character(len=12) :: text
      character(len=msg_len) :: msg

      msg = ""
      if (n > 0) then
         do k = 1, 4
            call put_nans(outs(k), n)
         end do
      end if
      call check_outputs("", gbar, "n", n, [gbar, outs], &
         "gbar, P_approach, P_retract, dPdg_approach and dPdg_retract", stat, msg)
      if (stat == wa_ok) call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok .and. n > 0) then         ! every argument before any work
         call c_f_pointer(gbar, g_in, [n])
         do k = 1, int(n)
            write (text, '(i0)') k - 1
            call check_range("gbar["//trim(text)//"]", g_in(k), 0.0_c_double, &
               huge(1.0_c_double), "[0, inf) (the mean gap over the wave "// &
               "amplitude)", stat, msg)
            if (stat /= wa_ok) exit
         end do
      end if
      if (stat == wa_ok) then
         allocate (res(max(0, n), 4))
         if (n > 0) then
            call gap_law(int(model), params, g_in, res(:, 1), res(:, 2), res(:, 3), &
               res(:, 4), stat, msg)
         else
            call gap_law(int(model), params, [real(c_double) ::], res(:, 1), res(:, 2), &
               res(:, 3), res(:, 4), stat, msg)
         end if
         call internal_capacity(stat, msg)
         if (stat == wa_ok .and. n > 0) then
            if (any(res(:, 1:2) /= res(:, 1:2)) .or. any(res(:, 3:4) /= res(:, 3:4))) &
               call set_error(wa_numerical_error, "gap_law: a value is NaN", stat, msg)
         end if
         if (stat == wa_ok .and. n > 0) then
            do k = 1, 4
               call store_reals(outs(k), res(:, k))
            end do
         end if
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function gap_law_core

   !> Validate, compute the critical values under gap control (NaN on failure).
   function gap_critical_core(model, alpha, mu, values, message, message_capacity) &
         result(status)
      integer(c_int), intent(in) :: model, message_capacity
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: values, message
      integer(c_int) :: status
      type(params_type) :: params
      type(gap_critical_type) :: crit
      integer :: stat
      character(len=msg_len) :: msg

      msg = ""
      stat = wa_ok
      call put_nans(values, int(gap_critical_count, c_int))
      if (.not. c_associated(values)) &
         call set_error(wa_invalid_argument, "values must not be NULL", stat, msg)
      if (stat == wa_ok) call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call gap_critical(int(model), params, crit, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) call store_reals(values, gap_critical_values(crit))
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function gap_critical_core

end module wa_capi_gap
