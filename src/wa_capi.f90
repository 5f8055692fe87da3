!> The C interface (SPEC section 5): every `bind(C)` export of the library and nothing
!> else; the declarations are in include/wavyadhesion.h.
!>
!> Every function taking pointers returns an `int` status (0 = ok) and writes its results
!> through the pointers; arrays are caller-allocated with an explicit capacity; nothing
!> is allocated for the caller to free. NULL result pointers are reported as
!> wa_invalid_argument, never dereferenced. The `_msg` variants also copy a message that
!> names the failing argument and its valid range into a caller buffer.
!> Thread safe: no state survives a call (the status texts are immutable data).
module wa_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_char, &
      c_associated, c_f_pointer, c_loc
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok, wa_invalid_argument, wa_capacity_too_small, &
      wa_numerical_error, set_error
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type
   use wa_kernels, only: westergaard_load, jkr_load
   use wa_models, only: check_model, model_equilibrium, model_roots
   implicit none
   private

   public :: capi_westergaard_load, capi_jkr_load, capi_equilibrium, capi_equilibrium_msg, &
      capi_roots, capi_roots_msg, capi_status_message

   !> Length of one status text, NUL included.
   integer, parameter :: text_len = 32
   !> Largest status code with a text of its own; others read "unknown status".
   integer, parameter :: last_status = wa_numerical_error
   !> Buffer for the library's messages before they are copied to C.
   integer, parameter :: msg_len = 256
   !> States held before asking for a larger buffer (more roots than this are rare).
   integer, parameter :: roots_buffer = 64

   !> NUL-terminated status texts, same wording as wa_status::status_message, index =
   !> status code, last entry = unknown. Immutable data: nothing ever assigns to it (the
   !> only way to hand C a `const char *` without allocating). Not mutable state.
   character(kind=c_char, len=text_len), target, save, protected :: &
      status_texts(0:last_status + 1) = [character(kind=c_char, len=text_len) :: &
      "ok"//c_null_char, &
      "invalid argument"//c_null_char, &
      "no solution"//c_null_char, &
      "iteration did not converge"//c_null_char, &
      "output capacity too small"//c_null_char, &
      "numerical error"//c_null_char, &
      "unknown status"//c_null_char]

contains

   !> double wa_westergaard_load(double a_star): P* = sin^2(pi a*); NaN outside [0, 1/2].
   function capi_westergaard_load(a_star) result(p) bind(C, name="wa_westergaard_load")
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      real(c_double) :: p
      p = westergaard_load(a_star)
   end function capi_westergaard_load

   !> double wa_jkr_load(double alpha, double a_star): P* = sin^2(pi a*) - alpha
   !> sqrt(tan(pi a*)); -Infinity at a* = 1/2; NaN for alpha < 0 or a* outside [0, 1/2].
   function capi_jkr_load(alpha, a_star) result(p) bind(C, name="wa_jkr_load")
      !> Johnson's parameter, >= 0
      real(c_double), value, intent(in) :: alpha
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      real(c_double) :: p
      p = jkr_load(alpha, a_star)
   end function capi_jkr_load

   !> int wa_equilibrium(model, alpha, mu, a_star, *c_star, *P_star, *zone_case):
   !> the principal equilibrium. On failure *c_star = *P_star = NaN, *zone_case = 0.
   function capi_equilibrium(model, alpha, mu, a_star, c_star, p_star, zone_case) &
         result(status) bind(C, name="wa_equilibrium")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> double *: receives c*
      type(c_ptr), value, intent(in) :: c_star
      !> double *: receives P*
      type(c_ptr), value, intent(in) :: p_star
      !> int *: receives the zone case (1, 2 or 3)
      type(c_ptr), value, intent(in) :: zone_case
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, status, msg)
   end function capi_equilibrium

   !> int wa_equilibrium_msg(..., char *message, int message_capacity): as
   !> wa_equilibrium, and copies the reason for a failure ("" on success), truncated and
   !> NUL-terminated, to `message` when it is not NULL and message_capacity > 0.
   function capi_equilibrium_msg(model, alpha, mu, a_star, c_star, p_star, zone_case, &
         message, message_capacity) result(status) bind(C, name="wa_equilibrium_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> double *: receives c*
      type(c_ptr), value, intent(in) :: c_star
      !> double *: receives P*
      type(c_ptr), value, intent(in) :: p_star
      !> int *: receives the zone case (1, 2 or 3)
      type(c_ptr), value, intent(in) :: zone_case
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, status, msg)
      call copy_message(msg, message, message_capacity)
   end function capi_equilibrium_msg

   !> int wa_roots(model, alpha, mu, a_star, capacity, c_star[], P_star[], zone_case[],
   !> *n_roots): every equilibrium at a*. *n_roots is the total; when it exceeds
   !> `capacity`, the first `capacity` states are written and the status is
   !> WA_CAPACITY_TOO_SMALL. On any other failure *n_roots = 0.
   function capi_roots(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots) result(status) bind(C, name="wa_roots")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Length of the three arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives c* of each state
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each state
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each state
      type(c_ptr), value, intent(in) :: zone_case
      !> int *: receives the number of states
      type(c_ptr), value, intent(in) :: n_roots
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, status, msg)
   end function capi_roots

   !> int wa_roots_msg(..., char *message, int message_capacity): as wa_roots, with the
   !> message of wa_equilibrium_msg.
   function capi_roots_msg(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, message, message_capacity) result(status) bind(C, name="wa_roots_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Length of the three arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives c* of each state
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each state
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each state
      type(c_ptr), value, intent(in) :: zone_case
      !> int *: receives the number of states
      type(c_ptr), value, intent(in) :: n_roots
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, status, msg)
      call copy_message(msg, message, message_capacity)
   end function capi_roots_msg

   !> const char *wa_status_message(int status): a static NUL-terminated text, never
   !> NULL ("unknown status" for codes the library does not return).
   function capi_status_message(status) result(text) bind(C, name="wa_status_message")
      !> A status code returned by the library
      integer(c_int), value, intent(in) :: status
      type(c_ptr) :: text
      if (status >= 0 .and. status <= last_status) then
         text = c_loc(status_texts(status))
      else
         text = c_loc(status_texts(last_status + 1))
      end if
   end function capi_status_message


   ! ---------------------------------------------------------------- internals

   !> Validate, solve, write the principal state (NaN, NaN, 0 on failure).
   subroutine equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, &
         status, msg)
      integer(c_int), intent(in) :: model
      real(c_double), intent(in) :: alpha, mu, a_star
      type(c_ptr), intent(in) :: c_star, p_star, zone_case
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      real(c_double), pointer :: c_out, p_out
      integer(c_int), pointer :: z_out
      type(params_type) :: params
      type(state_type) :: state
      integer :: stat

      msg = ""
      if (.not. (c_associated(c_star) .and. c_associated(p_star) .and. &
            c_associated(zone_case))) then
         call set_error(wa_invalid_argument, "c_star, P_star and zone_case must not be NULL", &
            stat, msg)
         status = int(stat, c_int)
         return
      end if
      call c_f_pointer(c_star, c_out)
      call c_f_pointer(p_star, p_out)
      call c_f_pointer(zone_case, z_out)
      c_out = ieee_value(c_out, ieee_quiet_nan)
      p_out = c_out
      z_out = 0
      call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call model_equilibrium(int(model), params, a_star, state, stat, msg)
      if (stat == wa_ok) then
         c_out = state%c_star
         p_out = state%p_star
         z_out = int(state%zone_case, c_int)
      end if
      status = int(stat, c_int)
   end subroutine equilibrium_core

   !> Validate, solve, write min(n, capacity) states and n (0 on failures other than
   !> a too small capacity).
   subroutine roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, status, msg)
      integer(c_int), intent(in) :: model, capacity
      real(c_double), intent(in) :: alpha, mu, a_star
      type(c_ptr), intent(in) :: c_star, p_star, zone_case, n_roots
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      integer(c_int), pointer :: n_out
      type(params_type) :: params
      type(state_type), allocatable :: states(:)
      integer :: stat, n

      msg = ""
      call check_roots_pointers(capacity, c_star, p_star, zone_case, n_roots, stat, msg)
      if (stat /= wa_ok) then
         status = int(stat, c_int)
         return
      end if
      call c_f_pointer(n_roots, n_out)
      n_out = 0
      n = 0
      call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) then
         allocate (states(min(int(capacity), roots_buffer)))
         call model_roots(int(model), params, a_star, states, n, stat, msg)
         if (stat == wa_capacity_too_small .and. n <= capacity) then   ! our buffer was short
            deallocate (states)
            allocate (states(n))
            msg = ""
            call model_roots(int(model), params, a_star, states, n, stat, msg)
         end if
      end if
      if (stat == wa_ok .or. stat == wa_capacity_too_small) then
         call store_states(states(1:min(n, size(states))), c_star, p_star, zone_case)
         n_out = int(n, c_int)
      end if
      status = int(stat, c_int)
   end subroutine roots_core

   !> n_roots must not be NULL; the arrays not NULL unless capacity is 0; capacity >= 0.
   subroutine check_roots_pointers(capacity, c_star, p_star, zone_case, n_roots, stat, msg)
      integer(c_int), intent(in) :: capacity
      type(c_ptr), intent(in) :: c_star, p_star, zone_case, n_roots
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=12) :: text

      stat = wa_ok
      if (.not. c_associated(n_roots)) then
         call set_error(wa_invalid_argument, "n_roots must not be NULL", stat, msg)
      else if (capacity < 0) then
         write (text, '(i0)') capacity
         call set_error(wa_invalid_argument, "capacity = "//trim(text)// &
            " is outside its valid range [0, inf)", stat, msg)
      else if (capacity > 0 .and. .not. (c_associated(c_star) .and. c_associated(p_star) &
            .and. c_associated(zone_case))) then
         call set_error(wa_invalid_argument, &
            "c_star, P_star and zone_case must not be NULL when capacity > 0", stat, msg)
      end if
   end subroutine check_roots_pointers

   !> Copy states into the caller's three arrays (nothing when there are none).
   subroutine store_states(states, c_star, p_star, zone_case)
      type(state_type), intent(in) :: states(:)
      type(c_ptr), intent(in) :: c_star, p_star, zone_case
      real(c_double), pointer :: c_out(:), p_out(:)
      integer(c_int), pointer :: z_out(:)
      integer :: k

      if (size(states) == 0) return
      call c_f_pointer(c_star, c_out, [size(states)])
      call c_f_pointer(p_star, p_out, [size(states)])
      call c_f_pointer(zone_case, z_out, [size(states)])
      do k = 1, size(states)
         c_out(k) = states(k)%c_star
         p_out(k) = states(k)%p_star
         z_out(k) = int(states(k)%zone_case, c_int)
      end do
   end subroutine store_states

   !> Copy msg (trailing blanks dropped), truncated to capacity - 1 bytes plus a NUL,
   !> into a C buffer; nothing when the buffer is NULL or capacity <= 0.
   subroutine copy_message(msg, buffer, capacity)
      character(len=*), intent(in) :: msg
      type(c_ptr), intent(in) :: buffer
      integer(c_int), intent(in) :: capacity
      character(kind=c_char), pointer :: out(:)
      integer :: n, i

      if (.not. c_associated(buffer) .or. capacity <= 0) return
      call c_f_pointer(buffer, out, [capacity])
      n = min(len_trim(msg), int(capacity) - 1)
      do i = 1, n
         out(i) = msg(i:i)
      end do
      out(n + 1) = c_null_char
   end subroutine copy_message

end module wa_capi
