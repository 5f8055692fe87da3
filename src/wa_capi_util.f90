!> display: none
!>
!> Marshalling for the C interface (modules wa_capi, wa_capi_gap, wa_capi_map,
!> wa_capi_lj, wa_capi_compat): the message copy, failure values written through C pointers, arrays
!> copied to the caller, and the checks of counts, capacities and NULL pointers that every
!> export shares. Nothing here is exported to C.
module wa_capi_util
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_char, &
      c_associated, c_f_pointer
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok, wa_invalid_argument, wa_capacity_too_small, &
      wa_numerical_error, wa_no_solution, set_error
   implicit none
   private

   public :: msg_len, copy_message, check_outputs, too_small, internal_capacity, &
      check_gbar_values, put_nan, put_int, put_nans, put_ints, store_reals, store_ints, &
      store_scalar

   !> Buffer for the library's messages before they are copied to C.
   integer, parameter :: msg_len = 256

contains

   !> Copy the message of a call that returned `status` into a C buffer: "" on WA_OK, else
   !> msg (trailing blanks dropped), truncated to capacity - 1 bytes plus a NUL; nothing
   !> when the buffer is NULL or capacity <= 0. The Fortran routines only promise errmsg
   !> on failure: one that recovers from an inner failure (a retry that succeeds) returns
   !> wa_ok with the inner message still in errmsg, which the header's "" on success must
   !> not pass on (wa_gap_law_msg did, e.g. "gap_path: no equilibrium near the branch").
   subroutine copy_message(status, msg, buffer, capacity)
      integer(c_int), intent(in) :: status
      character(len=*), intent(in) :: msg
      type(c_ptr), intent(in) :: buffer
      integer(c_int), intent(in) :: capacity
      character(kind=c_char), pointer :: out(:)
      integer :: n, i

      if (.not. c_associated(buffer) .or. capacity <= 0) return
      call c_f_pointer(buffer, out, [capacity])
      n = min(len_trim(msg), int(capacity) - 1)
      if (status == wa_ok) n = 0
      do i = 1, n
         out(i) = msg(i:i)
      end do
      out(n + 1) = c_null_char
   end subroutine copy_message

   !> The count pointer must not be NULL (when count_name is not empty); the size >= 0;
   !> the arrays not NULL unless the size is 0.
   subroutine check_outputs(count_name, count_ptr, size_name, capacity, arrays, array_names, &
         stat, msg)
      !> Name of the count pointer ("" when there is none)
      character(len=*), intent(in) :: count_name
      type(c_ptr), intent(in) :: count_ptr
      !> Name of the size argument ("capacity", "n_mu")
      character(len=*), intent(in) :: size_name
      integer(c_int), intent(in) :: capacity
      type(c_ptr), intent(in) :: arrays(:)
      !> Names of the arrays, for the message
      character(len=*), intent(in) :: array_names
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=12) :: text
      integer :: k

      stat = wa_ok
      if (len(count_name) > 0) then
         if (.not. c_associated(count_ptr)) then
            call set_error(wa_invalid_argument, count_name//" must not be NULL", stat, msg)
            return
         end if
      end if
      if (capacity < 0) then
         write (text, '(i0)') capacity
         call set_error(wa_invalid_argument, size_name//" = "//trim(text)// &
            " is outside its valid range [0, inf)", stat, msg)
         return
      end if
      if (capacity == 0) return
      do k = 1, size(arrays)
         if (.not. c_associated(arrays(k))) then
            call set_error(wa_invalid_argument, array_names//" must not be NULL when "// &
               size_name//" > 0", stat, msg)
            return
         end if
      end do
   end subroutine check_outputs

   !> WA_CAPACITY_TOO_SMALL with a message giving both sizes.
   subroutine too_small(what, items, n, capacity, stat, msg)
      character(len=*), intent(in) :: what, items
      integer, intent(in) :: n
      integer(c_int), intent(in) :: capacity
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=12) :: t_n, t_cap
      write (t_n, '(i0)') n
      write (t_cap, '(i0)') capacity
      call set_error(wa_capacity_too_small, "capacity = "//trim(t_cap)//" is too small: "// &
         what//" "//trim(t_n)//" "//items//" (the first "//trim(t_cap)//" were written)", &
         stat, msg)
   end subroutine too_small

   !> A wa_capacity_too_small from the numerics below a function whose only capacity is
   !> the caller's (checked here) is an internal buffer running short: report it as
   !> wa_numerical_error, so the caller never reads it as "your array is too small".
   subroutine internal_capacity(stat, msg)
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: msg
      if (stat /= wa_capacity_too_small) return
      stat = wa_numerical_error
      msg = "internal buffer too small: "//msg
   end subroutine internal_capacity

   !> wa_ok when every mean gap is a number >= 0, else wa_no_solution (never a NaN or the
   !> "not computed" -1 with an OK status).
   subroutine check_gbar_values(gbar, stat, msg)
      real(c_double), intent(in) :: gbar(:)
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: msg
      integer :: k
      do k = 1, size(gbar)
         if (.not. (gbar(k) >= 0.0_c_double .and. gbar(k) <= huge(gbar(k)))) then
            call set_error(wa_no_solution, "gbar: the mean gap of a state is not defined "// &
               "(not a finite number >= 0)", stat, msg)
            return
         end if
      end do
   end subroutine check_gbar_values

   !> *ptr = NaN unless ptr is NULL (a failure's value, written before any check).
   subroutine put_nan(ptr)
      type(c_ptr), intent(in) :: ptr
      real(c_double), pointer :: out
      if (.not. c_associated(ptr)) return
      call c_f_pointer(ptr, out)
      out = ieee_value(out, ieee_quiet_nan)
   end subroutine put_nan

   !> *ptr = value unless ptr is NULL.
   subroutine put_int(ptr, value)
      type(c_ptr), intent(in) :: ptr
      integer, intent(in) :: value
      integer(c_int), pointer :: out
      if (.not. c_associated(ptr)) return
      call c_f_pointer(ptr, out)
      out = int(value, c_int)
   end subroutine put_int

   !> ptr[0..n-1] = NaN unless ptr is NULL (n > 0).
   subroutine put_nans(ptr, n)
      type(c_ptr), intent(in) :: ptr
      integer(c_int), intent(in) :: n
      real(c_double), pointer :: out(:)
      if (.not. c_associated(ptr)) return
      call c_f_pointer(ptr, out, [n])
      out = ieee_value(1.0_c_double, ieee_quiet_nan)
   end subroutine put_nans

   !> ptr[0..n-1] = value unless ptr is NULL (n > 0).
   subroutine put_ints(ptr, n, value)
      type(c_ptr), intent(in) :: ptr
      integer(c_int), intent(in) :: n
      integer, intent(in) :: value
      integer(c_int), pointer :: out(:)
      if (.not. c_associated(ptr)) return
      call c_f_pointer(ptr, out, [n])
      out = int(value, c_int)
   end subroutine put_ints

   !> *ptr = value (ptr checked non-NULL by the caller).
   subroutine store_scalar(ptr, value)
      type(c_ptr), intent(in) :: ptr
      real(c_double), intent(in) :: value
      real(c_double), pointer :: out
      call c_f_pointer(ptr, out)
      out = value
   end subroutine store_scalar

   !> Copy values into a caller's double array (nothing when there are none).
   subroutine store_reals(ptr, values)
      type(c_ptr), intent(in) :: ptr
      real(c_double), intent(in) :: values(:)
      real(c_double), pointer :: out(:)
      if (size(values) == 0) return
      call c_f_pointer(ptr, out, [size(values)])
      out = values
   end subroutine store_reals

   !> Copy values into a caller's int array (nothing when there are none).
   subroutine store_ints(ptr, values)
      type(c_ptr), intent(in) :: ptr
      integer, intent(in) :: values(:)
      integer(c_int), pointer :: out(:)
      if (size(values) == 0) return
      call c_f_pointer(ptr, out, [size(values)])
      out = int(values, c_int)
   end subroutine store_ints

end module wa_capi_util
