!> Agreement with the mpmath reference tables in test/data (tools/reference/make_reference.py):
!> every state at every tabulated (alpha, mu, a*), c* and P* to the accuracy target's tolerance (doc/accuracy-performance.md).
module test_reference
   use wavyadhesion
   use wa_kinds, only: wp
   use harness, only: error_type, unittest_type, new_unittest, check
   implicit none
   private

   public :: collect_reference, compare_table

   !> The accuracy target (doc/accuracy-performance.md): relative 1e-12 in c* and P*, absolute 1e-12 where |P*| < 1e-3.
   real(wp), parameter :: rtol = 1.0e-12_wp, p_abs_below = 1.0e-3_wp

contains

   subroutine collect_reference(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("westergaard_table", test_westergaard), &
         new_unittest("jkr_table", test_jkr), &
         new_unittest("dw_table", test_dw), &
         new_unittest("md_table", test_md), &
         new_unittest("dw_extended_table", test_dw_extended), &
         new_unittest("md_extended_table", test_md_extended)]
   end subroutine collect_reference

   subroutine test_westergaard(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_closed_form("test/data/westergaard.txt", model_westergaard, error)
   end subroutine test_westergaard

   subroutine test_jkr(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_closed_form("test/data/jkr.txt", model_jkr, error)
   end subroutine test_jkr

   subroutine test_dw(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_table("test/data/dw.txt", model_dw, rtol, .false., error)
   end subroutine test_dw

   subroutine test_md(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_table("test/data/md.txt", model_md, rtol, .false., error)
   end subroutine test_md

   !> Beyond the accuracy target's main range the measured accuracy is documented in
   !> doc/theory.md; here every point must be accurate to 1e-9 or carry a status.
   subroutine test_dw_extended(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_table("test/data/dw_extended.txt", model_dw, 1.0e-9_wp, .true., error)
   end subroutine test_dw_extended

   subroutine test_md_extended(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_table("test/data/md_extended.txt", model_md, 1.0e-9_wp, .true., error)
   end subroutine test_md_extended

   !> Columns a_star P_star (westergaard) or alpha a_star P_star (jkr).
   subroutine compare_closed_form(path, model, error)
      character(len=*), intent(in) :: path
      integer, intent(in) :: model
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: alpha, a, p, got, worst
      integer :: unit, ios, rows
      character(len=512) :: line

      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      call check(error, ios == 0, "cannot open "//path)
      if (allocated(error)) return
      worst = 0.0_wp
      rows = 0
      alpha = 0.0_wp
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         if (model == model_jkr) then
            read (line, *) alpha, a, p
            got = jkr_load(alpha, a)
         else
            read (line, *) a, p
            got = westergaard_load(a)
         end if
         rows = rows + 1
         worst = max(worst, abs(got - p)/p_scale(p))
      end do
      close (unit)
      print '(4x,a,i0,a,es9.2)', path//": ", rows, " rows, max scaled error ", worst
      call check(error, rows > 0 .and. worst <= 1.0e-14_wp, path//": closed form off")
   end subroutine compare_closed_form

   !> Columns alpha mu a_star c_star gap P_star zone_case, one row per state; rows of
   !> one (alpha, mu, a*) are consecutive. Prints the largest errors it measured.
   subroutine compare_table(path, model, tol, status_allowed, error)
      character(len=*), intent(in) :: path
      integer, intent(in) :: model
      real(wp), intent(in) :: tol
      !> May a point return a status instead of its states (extended range)?
      logical, intent(in) :: status_allowed
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: ref(:, :)
      integer, allocatable :: zone(:)
      real(wp) :: worst_c, worst_p, worst_gap
      integer :: first, last, nrows, n_status, n_mismatch

      call read_table(path, ref, zone, nrows)
      call check(error, nrows > 0, "cannot read "//path)
      if (allocated(error)) return
      worst_c = 0; worst_p = 0; worst_gap = 0
      n_status = 0; n_mismatch = 0
      first = 1
      do while (first <= nrows)
         last = first
         do while (last < nrows)
            if (any(ref(1:3, last + 1) /= ref(1:3, first))) exit
            last = last + 1
         end do
         call compare_point(model, ref(:, first:last), zone(first:last), worst_c, worst_p, &
            worst_gap, n_status, n_mismatch)
         first = last + 1
      end do
      print '(4x,a,i0,a,3(es9.2,a),i0,a,i0)', path//": ", nrows, " states; max rel err c* ", &
         worst_c, ", P* ", worst_p, ", c*-a* ", worst_gap, "; points with status ", &
         n_status, ", root-count mismatches ", n_mismatch
      call check(error, n_mismatch == 0, path//": number or kind of roots differs")
      call check(error, status_allowed .or. n_status == 0, path//": a point returned a status")
      call check(error, worst_c <= tol .and. worst_p <= tol, path//": error above tolerance")
   end subroutine compare_table

   subroutine compare_point(model, ref, zone, worst_c, worst_p, worst_gap, n_status, n_mismatch)
      integer, intent(in) :: model
      real(wp), intent(in) :: ref(:, :)
      integer, intent(in) :: zone(:)
      real(wp), intent(inout) :: worst_c, worst_p, worst_gap
      integer, intent(inout) :: n_status, n_mismatch
      type(params_type) :: params
      type(state_type) :: states(8)
      integer :: status, n, k

      call new_params(ref(1, 1), ref(2, 1), params, status)
      if (model == model_dw) then
         call dw_roots(params, ref(3, 1), states, n, status)
      else
         call md_roots(params, ref(3, 1), states, n, status)
      end if
      if (status /= wa_ok) then
         n_status = n_status + 1
         return
      end if
      if (n /= size(zone)) then
         n_mismatch = n_mismatch + 1
         return
      end if
      do k = 1, n
         if (states(k)%zone_case /= zone(k)) n_mismatch = n_mismatch + 1
         worst_c = max(worst_c, abs(states(k)%c_star - ref(4, k))/ref(4, k))
         worst_gap = max(worst_gap, abs(states(k)%gap_width - ref(5, k))/ref(5, k))
         worst_p = max(worst_p, abs(states(k)%p_star - ref(6, k))/p_scale(ref(6, k)))
      end do
   end subroutine compare_point

   subroutine read_table(path, ref, zone, nrows)
      character(len=*), intent(in) :: path
      real(wp), allocatable, intent(out) :: ref(:, :)
      integer, allocatable, intent(out) :: zone(:)
      integer, intent(out) :: nrows
      character(len=1024) :: line
      integer :: unit, ios, pass

      nrows = 0
      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      if (ios /= 0) return
      do pass = 1, 2
         if (pass == 2) then
            allocate (ref(6, nrows), zone(nrows))
            rewind (unit)
            nrows = 0
         end if
         do
            read (unit, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
            nrows = nrows + 1
            if (pass == 2) read (line, *) ref(:, nrows), zone(nrows)
         end do
      end do
      close (unit)
   end subroutine read_table

   !> Relative error for |P*| >= 1e-3, absolute below (doc/accuracy-performance.md).
   pure real(wp) function p_scale(p)
      real(wp), intent(in) :: p
      p_scale = merge(abs(p), 1.0_wp, abs(p) >= p_abs_below)
   end function p_scale

end module test_reference
