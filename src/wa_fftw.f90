!> display: none
!>
!> Raw `bind(C)` interfaces to the parts of FFTW3 the library uses (real-to-real
!> transforms of one dimension, to and from the halfcomplex order). Not re-exported.
!>
!> Plans are made by the caller, held in its workspace and destroyed by it (no module
!> state); fftw_make_planner_thread_safe is called before each planning, so that callers
!> on several threads may plan at once (executing a plan is thread-safe in FFTW).
module wa_fftw
   use, intrinsic :: iso_c_binding, only: c_int, c_ptr, c_double
   implicit none
   private

   !> Planner flags. FFTW_ESTIMATE plans by heuristics, without trial transforms (the arrays are left
   !> untouched); with FFTW_UNALIGNED the plan may be executed on arrays of any alignment.
   integer(c_int), parameter, public :: fftw_estimate = 64, fftw_unaligned = 2
   !> Kinds of r2r transform: real to halfcomplex and back (unnormalised)
   integer(c_int), parameter, public :: fftw_r2hc = 0, fftw_hc2r = 1

   public :: fftw_plan_r2r_1d, fftw_execute_r2r, fftw_destroy_plan, &
      fftw_make_planner_thread_safe

   interface
      function fftw_plan_r2r_1d(n, in, out, kind, flags) result(plan) &
            bind(C, name="fftw_plan_r2r_1d")
         import :: c_int, c_ptr, c_double
         integer(c_int), value, intent(in) :: n
         real(c_double), intent(inout) :: in(*), out(*)
         integer(c_int), value, intent(in) :: kind, flags
         type(c_ptr) :: plan
      end function fftw_plan_r2r_1d

      subroutine fftw_execute_r2r(plan, in, out) bind(C, name="fftw_execute_r2r")
         import :: c_ptr, c_double
         type(c_ptr), value, intent(in) :: plan
         real(c_double), intent(inout) :: in(*), out(*)
      end subroutine fftw_execute_r2r

      subroutine fftw_destroy_plan(plan) bind(C, name="fftw_destroy_plan")
         import :: c_ptr
         type(c_ptr), value, intent(in) :: plan
      end subroutine fftw_destroy_plan

      subroutine fftw_make_planner_thread_safe() bind(C, name="fftw_make_planner_thread_safe")
      end subroutine fftw_make_planner_thread_safe
   end interface

end module wa_fftw
