!> display: none
!>
!> Argument checks shared by every public entry point: each failure names the
!> argument, its value and its valid range.
module wa_validate
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_invalid_argument, set_error
   implicit none
   private

   public :: check_range, optval

   !> The value of an optional argument, or `default` where it is absent
   !> (stdlib's optval): optval(tol_in, 1.0e-9_wp), optval(flag, .false.).
   interface optval
      module procedure optval_logical, optval_integer, optval_real
   end interface optval

contains

   !> status = wa_ok if lo <(=) x <(=) hi, else wa_invalid_argument with a message
   !> such as "a_star = 7.0E-01 is outside its valid range [0, 1/2]".
   pure subroutine check_range(name, x, lo, hi, range_text, status, errmsg, &
         lo_open, hi_open)
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: x, lo, hi
      !> The range as the user should read it, e.g. "(0, inf)" or "[0, 1/2]".
      character(len=*), intent(in) :: range_text
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      logical, intent(in), optional :: lo_open, hi_open
      logical :: bad
      character(len=32) :: xtext

      bad = ieee_is_nan(x)
      if (.not. bad) then
         if (optval(lo_open, .false.)) then
            bad = .not. (x > lo)
         else
            bad = .not. (x >= lo)
         end if
         if (optval(hi_open, .false.)) then
            bad = bad .or. .not. (x < hi)
         else
            bad = bad .or. .not. (x <= hi)
         end if
         if (hi > huge(hi)) bad = bad .or. .not. ieee_is_finite(x)
      end if
      if (bad) then
         if (abs(x) >= 1.0e100_wp .or. (x /= 0.0_wp .and. abs(x) < 1.0e-99_wp)) then
            write (xtext, '(es14.5e3)') x        ! three exponent digits keep the letter E
         else
            write (xtext, '(es12.5)') x
         end if
         call set_error(wa_invalid_argument, name//" = "//trim(adjustl(xtext))// &
            " is outside its valid range "//range_text, status, errmsg)
      else
         status = wa_ok
      end if
   end subroutine check_range

   pure logical function optval_logical(x, default) result(y)
      logical, intent(in), optional :: x
      logical, intent(in) :: default
      y = default
      if (present(x)) y = x
   end function optval_logical

   pure integer function optval_integer(x, default) result(y)
      integer, intent(in), optional :: x
      integer, intent(in) :: default
      y = default
      if (present(x)) y = x
   end function optval_integer

   pure real(wp) function optval_real(x, default) result(y)
      real(wp), intent(in), optional :: x
      real(wp), intent(in) :: default
      y = default
      if (present(x)) y = x
   end function optval_real

end module wa_validate
