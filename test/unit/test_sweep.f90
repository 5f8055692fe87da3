!> critical_sweep keeps every good row and mechanism_change is robust (issue 9): each row
!> equals load_path at its mu or, where load_path fails, holds NaN, -1 and that status;
!> the bisection is bounded and starts arithmetic from mu = 0.
module test_sweep
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   use wavyadhesion
   use wa_kinds, only: wp
   implicit none
   private

   public :: collect_sweep

contains

   subroutine collect_sweep(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("rows_equal_load_path_or_fail_alone", test_rows), &
         new_unittest("row_status_and_messages", test_row_outputs), &
         new_unittest("mechanism_change_from_mu_zero", test_from_zero), &
         new_unittest("mechanism_change_dw_alpha03", test_dw_change), &
         new_unittest("mechanism_change_in_failure_window", test_window)]
   end subroutine collect_sweep

   !> MD alpha = 1 around its P_pf mechanism change (a failure window in issue 9 item 4)
   !> and DW at mu = 0 (item 3): whichever rows fail, the others are load_path's values.
   subroutine test_rows(error)
      type(error_type), allocatable, intent(out) :: error
      call check_rows(error, model_md, 1.0_wp, [0.5_wp, 0.7936921_wp, &
         0.79369860901363931_wp, 0.7937005_wp, 2.0_wp])
      if (allocated(error)) return
      call check_rows(error, model_dw, 0.3_wp, [1.0_wp, 0.0_wp, 5.0_wp])
   end subroutine test_rows

   subroutine check_rows(error, model, alpha, mu)
      type(error_type), allocatable, intent(inout) :: error
      integer, intent(in) :: model
      real(wp), intent(in) :: alpha, mu(:)
      real(wp) :: p_fc(size(mu)), p_pf(size(mu))
      integer :: fcm(size(mu)), pfm(size(mu)), rows(size(mu)), status, i, stat, first
      character(len=256) :: msg, row_msg(size(mu))
      type(params_type) :: params
      type(path_type) :: path
      msg = ""
      call critical_sweep(model, alpha, mu, p_fc, p_pf, fcm, pfm, status, msg, rows, row_msg)
      first = wa_ok
      do i = 1, size(mu)
         call new_params(alpha, mu(i), params, stat)
         call load_path(model, params, path, stat)
         call check(error, rows(i) == stat, "row status equals load_path's")
         if (stat == wa_ok) then
            call check(error, p_fc(i) == path%p_fc .and. p_pf(i) == path%p_pf .and. &
               fcm(i) == path%fc_mechanism .and. pfm(i) == path%pf_mechanism, &
               "good row equals load_path")
            call check(error, len_trim(row_msg(i)) == 0, "no message on a good row")
         else
            call check(error, ieee_is_nan(p_fc(i)) .and. ieee_is_nan(p_pf(i)) .and. &
               fcm(i) == -1 .and. pfm(i) == -1, "failing row: NaN and -1")
            call check(error, len_trim(row_msg(i)) > 0, "failing row has its message")
            if (first == wa_ok) first = stat
         end if
         if (allocated(error)) return
      end do
      call check(error, status == first, "sweep status is the first failing row's")
      if (first /= wa_ok) call check(error, index(msg, "rows failed") > 0, &
         "sweep message counts the failing rows: "//trim(msg))
   end subroutine check_rows

   !> Without the optional outputs the sweep still goes on past a failure.
   subroutine test_row_outputs(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: p_fc(3), p_pf(3)
      integer :: fcm(3), pfm(3), status
      call critical_sweep(model_dw, 0.3_wp, [1.0_wp, -1.0_wp, 5.0_wp], p_fc, p_pf, fcm, pfm, &
         status)
      call check(error, status == wa_invalid_argument, "invalid mu reported")
      call check(error, ieee_is_nan(p_fc(2)) .and. fcm(2) == -1, "invalid row NaN")
      call check(error, .not. ieee_is_nan(p_fc(1)) .and. .not. ieee_is_nan(p_pf(3)), &
         "other rows computed")
   end subroutine test_row_outputs

   !> From mu_lo = 0 the bisection cannot be geometric; it must still end, at the MD
   !> P_pf change near mu = 0.575 (alpha 0.3), within its 200 steps.
   subroutine test_from_zero(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: mu_c, bracket(2)
      integer :: status
      call mechanism_change(model_md, 0.3_wp, 2, 0.0_wp, 1.0_wp, mu_c, status, &
         bracket=bracket)
      call check(error, status == wa_ok, "converged")
      call check(error, mu_c > 0.57_wp .and. mu_c < 0.58_wp, "change near 0.575")
      call check(error, bracket(2) - bracket(1) <= 1.0e-10_wp*bracket(2), "bracket width")
   end subroutine test_from_zero

   !> DW alpha 0.3: P_pf gradual -> jump case 1 at mu = 0.580 (the C test's value), where
   !> the fold contact is lost from passes a* = a_point_pull_off = 1e-3.
   subroutine test_dw_change(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: mu_c
      integer :: status
      call mechanism_change(model_dw, 0.3_wp, 2, 0.1_wp, 1.0_wp, mu_c, status)
      call check(error, status == wa_ok, "converged")
      call check_close(error, mu_c, 0.5799_wp, 1.0e-3_wp, what="mu_c")
   end subroutine test_dw_change

   !> MD alpha = 1: the P_pf change lies inside a window where load_path failed (issue 9
   !> item 4). The bisection either locates it (status ok) or stops with a bracket that
   !> holds the window; it never fails outright or leaves [mu_lo, mu_hi].
   subroutine test_window(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: mu_c, bracket(2)
      integer :: status
      character(len=256) :: msg
      msg = ""
      call mechanism_change(model_md, 1.0_wp, 2, 0.6_wp, 0.9_wp, mu_c, status, msg, bracket)
      call check(error, bracket(1) >= 0.6_wp .and. bracket(2) <= 0.9_wp .and. &
         bracket(1) < bracket(2), "bracket inside the interval")
      call check(error, mu_c >= bracket(1) .and. mu_c <= bracket(2), "mu_c in the bracket")
      call check(error, bracket(1) > 0.7936_wp .and. bracket(2) < 0.7938_wp, &
         "bracket around 0.79370")
      if (status /= wa_ok) call check(error, index(msg, "not located further") > 0, &
         "message says where it stopped: "//trim(msg))
   end subroutine test_window

end module test_sweep
