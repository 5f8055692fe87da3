!> display: none
!>
!> The C interface, the adhesion map: wa_adhesion_map calls the library's adhesion_map
!> (module wa_map) once and lists its boundary points for the caller (declarations in
!> include/wavyadhesion.h; the conventions in wa_capi).
module wa_capi_map
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_associated, c_f_pointer
   use wa_status, only: wa_ok, wa_invalid_argument, set_error
   use wa_map, only: map_type, adhesion_map, map_n_alpha_max
   use wa_capi_util, only: msg_len, copy_message, check_outputs, too_small, &
      internal_capacity, put_int
   implicit none
   private

   public :: capi_adhesion_map
   public :: map_core

contains

   !> int wa_adhesion_map(model, control, n_alpha, alpha[], mu_lo, mu_hi, n_mu, capacity,
   !> boundary_code[], alpha_out[], mu_out[], *n_out, message, message_capacity): the
   !> boundary points of the adhesion map (adhesion_map, discovery scan over n_mu
   !> log-spaced mu), curve after curve, each curve in increasing alpha, for control
   !> WA_MAP_CONTROL_LOAD (codes 1xx, 2xx), WA_MAP_CONTROL_GAP (3xx, 4xx) or
   !> WA_MAP_CONTROL_BOTH. *n_out receives the number of points; when it exceeds capacity
   !> the first `capacity` are written and WA_CAPACITY_TOO_SMALL is returned. On any other
   !> failure *n_out = 0 (when n_out is not NULL) and the arrays are not written.
   function capi_adhesion_map(model, control, n_alpha, alpha, mu_lo, mu_hi, n_mu, capacity, &
         boundary_code, alpha_out, mu_out, n_out, message, message_capacity) result(status) &
         bind(C, name="wa_adhesion_map")
      !> WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> WA_MAP_CONTROL_LOAD, WA_MAP_CONTROL_GAP or WA_MAP_CONTROL_BOTH
      integer(c_int), value, intent(in) :: control
      !> Number of alpha values, in [1, 100000]
      integer(c_int), value, intent(in) :: n_alpha
      !> const double[n_alpha]: strictly increasing alpha values (the supported domain)
      type(c_ptr), value, intent(in) :: alpha
      !> The mu range, mu_lo < mu_hi, both in [WA_MU_MIN, WA_MU_MAX]
      real(c_double), value, intent(in) :: mu_lo, mu_hi
      !> Points of the discovery scan in mu, in [2, 100000] (0.2 used 60)
      integer(c_int), value, intent(in) :: n_mu
      !> Length of the three output arrays, >= 0 (they may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> int[capacity]: receives the boundary code of each point
      type(c_ptr), value, intent(in) :: boundary_code
      !> double[capacity]: receive alpha and mu of each point
      type(c_ptr), value, intent(in) :: alpha_out, mu_out
      !> int *: receives the number of points
      type(c_ptr), value, intent(in) :: n_out
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = map_core(model, control, n_alpha, alpha, mu_lo, mu_hi, n_mu, capacity, &
         boundary_code, [alpha_out, mu_out], n_out, message, message_capacity)
   end function capi_adhesion_map

   !> Validate the C arguments, build the map (adhesion_map validates the rest), write
   !> min(n, capacity) points and n. reals = [alpha_out, mu_out].
   function map_core(model, control, n_alpha, alpha, mu_lo, mu_hi, n_mu, capacity, &
         boundary_code, reals, n_out, message, message_capacity) result(status)
      integer(c_int), intent(in) :: model, control, n_alpha, n_mu, capacity, message_capacity
      real(c_double), intent(in) :: mu_lo, mu_hi
      type(c_ptr), intent(in) :: alpha, boundary_code, reals(2), n_out, message
      integer(c_int) :: status
      integer(c_int), pointer :: n_ptr, codes(:)
      real(c_double), pointer :: a_in(:), a_out(:), m_out(:)
      type(map_type) :: map
      integer :: stat, c, p, n
      character(len=12) :: text
      character(len=msg_len) :: msg

      msg = ""
      call put_int(n_out, 0)
      call check_outputs("n_out", n_out, "capacity", capacity, [boundary_code, reals], &
         "boundary_code, alpha_out and mu_out", stat, msg)
      if (stat == wa_ok .and. (n_alpha < 1 .or. n_alpha > map_n_alpha_max)) then
         write (text, '(i0)') n_alpha
         call set_error(wa_invalid_argument, "n_alpha = "//trim(text)//" is outside its "// &
            "valid range [1, 100000]", stat, msg)
      else if (stat == wa_ok .and. .not. c_associated(alpha)) then
         call set_error(wa_invalid_argument, "alpha must not be NULL", stat, msg)
      end if
      if (stat == wa_ok) then
         call c_f_pointer(alpha, a_in, [n_alpha])
         call adhesion_map(int(model), a_in, mu_lo, mu_hi, int(n_mu), map, stat, msg, &
            control=int(control))
      end if
      call internal_capacity(stat, msg)
      if (stat == wa_ok) then
         if (capacity > 0) then
            call c_f_pointer(boundary_code, codes, [capacity])
            call c_f_pointer(reals(1), a_out, [capacity])
            call c_f_pointer(reals(2), m_out, [capacity])
         end if
         n = 0
         do c = 1, map%n_boundaries              ! curve after curve, the first capacity points
            do p = 1, map%boundary(c)%n
               n = n + 1
               if (n > capacity) cycle
               codes(n) = int(map%boundary(c)%code, c_int)
               a_out(n) = map%boundary(c)%alpha(p)
               m_out(n) = map%boundary(c)%mu(p)
            end do
         end do
         call c_f_pointer(n_out, n_ptr)
         n_ptr = int(n, c_int)
         if (n > capacity) call too_small("the map has", "points", n, capacity, stat, msg)
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function map_core

end module wa_capi_map
