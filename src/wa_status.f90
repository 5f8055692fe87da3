!> Status codes returned by every routine of the library, and their messages.
!>
!> Library code never stops or prints: it returns one of these codes and, where the
!> caller passes one, a message that names the offending argument and its valid range.
module wa_status
   implicit none
   private

   integer, parameter, public :: wa_ok = 0
   !> An argument is NaN, infinite or outside its valid range.
   integer, parameter, public :: wa_invalid_argument = 1
   !> The equations have no solution of the kind asked for (e.g. no case-1 root).
   integer, parameter, public :: wa_no_solution = 2
   !> An iteration did not reach its tolerance; no value is returned as if converged.
   integer, parameter, public :: wa_not_converged = 3
   !> A caller-supplied array is too small; only what fits was written.
   integer, parameter, public :: wa_capacity_too_small = 4
   !> A numerical building block (GSL, quadrature) failed.
   integer, parameter, public :: wa_numerical_error = 5

   public :: status_message, set_error

contains

   !> Short, fixed description of a status code (never empty).
   pure function status_message(status) result(msg)
      !> A status code (wa_ok ... wa_numerical_error); any other value gives "unknown status"
      integer, intent(in) :: status
      character(len=:), allocatable :: msg
      select case (status)
      case (wa_ok);                  msg = "ok"
      case (wa_invalid_argument);    msg = "invalid argument"
      case (wa_no_solution);         msg = "no solution"
      case (wa_not_converged);       msg = "iteration did not converge"
      case (wa_capacity_too_small);  msg = "output capacity too small"
      case (wa_numerical_error);     msg = "numerical error"
      case default;                  msg = "unknown status"
      end select
   end function status_message

   !> Set `status` and, if present, the caller's message buffer.
   pure subroutine set_error(code, text, status, errmsg)
      integer, intent(in) :: code
      character(len=*), intent(in) :: text
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      status = code
      if (present(errmsg)) errmsg = text
   end subroutine set_error

end module wa_status
