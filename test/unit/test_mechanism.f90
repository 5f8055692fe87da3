!> Tests of wa_mechanism, the reverse-communication bisection for where an integer
!> mechanism changes with mu, on a synthetic step mechanism(mu) = merge(1, 0, mu > step)
!> whose change is known exactly, with trial points made to fail on purpose.
module test_mechanism
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_no_solution, wa_not_converged, wa_numerical_error
   use wa_mechanism, only: mechanism_bisection, bisection_start, bisection_next, &
      bisection_tell, bisection_result
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   implicit none
   private

   public :: collect_mechanism

   !> Where the synthetic mechanism changes
   real(wp), parameter :: step = 0.37_wp
   !> The bisection's relative width (its header: 1e-10)
   real(wp), parameter :: rel_width = 1.0e-10_wp
   !> Trial fractions of the bracket: the midpoint, then a quarter from either end
   real(wp), parameter :: three_tries(*) = [0.5_wp, 0.25_wp, 0.75_wp]
   !> More mu than any run here asks for
   integer, parameter :: max_asked = 400

   !> One run of the bisection: what it asked and what it returned.
   type :: run_type
      real(wp) :: asked(max_asked) = 0.0_wp
      integer :: nasked = 0, nfailed = 0
      real(wp) :: mu_change = 0.0_wp, bracket(2) = 0.0_wp
      integer :: status = -1
      character(len=512) :: msg = ""
   end type run_type

contains

   subroutine collect_mechanism(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("geometric_bracket_converges", test_geometric), &
         new_unittest("arithmetic_from_zero", test_arithmetic), &
         new_unittest("failed_trial_takes_next_fraction", test_next_fraction), &
         new_unittest("same_mechanism_no_solution", test_no_solution), &
         new_unittest("every_trial_fails", test_every_trial_fails), &
         new_unittest("failing_zone_keeps_bracket", test_failing_zone), &
         new_unittest("end_fails", test_end_fails), &
         new_unittest("not_converged_after_200_steps", test_not_converged)]
   end subroutine collect_mechanism

   !> Runs the bisection on [mu_lo, mu_hi] for merge(1, 0, mu > change); every mu in the
   !> open interval (fail_lo, fail_hi) fails with wa_numerical_error.
   subroutine run_bisection(mu_lo, mu_hi, tries, change, fail_lo, fail_hi, run)
      real(wp), intent(in) :: mu_lo, mu_hi, tries(:), change, fail_lo, fail_hi
      type(run_type), intent(out) :: run
      type(mechanism_bisection) :: bis
      real(wp) :: mu
      logical :: more
      call bisection_start(bis, mu_lo, mu_hi, tries, "test mechanism")
      do
         call bisection_next(bis, mu, more)
         if (.not. more) exit
         if (run%nasked == max_asked) exit   ! a runaway bisection: the checks fail below
         run%nasked = run%nasked + 1
         run%asked(run%nasked) = mu
         if (mu > fail_lo .and. mu < fail_hi) then
            run%nfailed = run%nfailed + 1
            call bisection_tell(bis, -1, wa_numerical_error, "synthetic failure")
         else
            call bisection_tell(bis, merge(1, 0, mu > change), wa_ok, "")
         end if
      end do
      call bisection_result(bis, run%mu_change, run%status, run%msg, run%bracket)
   end subroutine run_bisection

   !> The bracket is an interval of computed points around the change, narrowed to the
   !> relative width.
   subroutine check_converged(error, run, what)
      type(error_type), allocatable, intent(inout) :: error
      type(run_type), intent(in) :: run
      character(len=*), intent(in) :: what
      call check(error, run%status == wa_ok, what//": status "//trim(run%msg))
      call check(error, run%nasked < max_asked, what//": runaway bisection")
      call check_close(error, run%mu_change, step, rel_width, what=what//": mu_change")
      call check(error, run%bracket(1) <= step .and. step < run%bracket(2), &
         what//": bracket holds the change")
      call check(error, run%bracket(2) - run%bracket(1) <= rel_width*run%bracket(2), &
         what//": bracket narrowed to 1e-10 relative")
   end subroutine check_converged

   !> mu_lo > 0: the trial points are geometric midpoints, sqrt(mu_lo*mu_hi) first.
   subroutine test_geometric(error)
      type(error_type), allocatable, intent(out) :: error
      type(run_type) :: run
      call run_bisection(0.01_wp, 10.0_wp, [0.5_wp], step, 1.0_wp, 0.0_wp, run)
      call check_converged(error, run, "geometric")
      call check(error, run%asked(1) == 0.01_wp .and. run%asked(2) == 10.0_wp, &
         "asks mu_lo, then mu_hi")
      ! sqrt(0.1) (the arithmetic midpoint would be 5.005); mechanism 0 there, so the
      ! next is sqrt(sqrt(0.1)*10) = 10**0.25
      call check_close(error, run%asked(3), sqrt(0.1_wp), 1.0e-15_wp, what="first trial")
      call check_close(error, run%asked(4), sqrt(sqrt(10.0_wp)), 1.0e-15_wp, &
         what="second trial")
      call check(error, run%nfailed == 0, "no failure")
   end subroutine test_geometric

   !> mu_lo = 0: arithmetic midpoints while the lower end is 0, then geometric.
   subroutine test_arithmetic(error)
      type(error_type), allocatable, intent(out) :: error
      type(run_type) :: run
      call run_bisection(0.0_wp, 1.0_wp, [0.5_wp], step, 1.0_wp, 0.0_wp, run)
      call check_converged(error, run, "arithmetic")
      ! 0.5 (mechanism 1: hi = 0.5), 0.25 (0: lo = 0.25), then sqrt(0.25*0.5)
      call check(error, run%asked(3) == 0.5_wp, "first trial 0.5")
      call check(error, run%asked(4) == 0.25_wp, "second trial 0.25")
      call check_close(error, run%asked(5), sqrt(0.125_wp), 1.0e-15_wp, &
         what="geometric once the lower end is > 0")
   end subroutine test_arithmetic

   !> A trial point that fails is replaced by the next fraction of `tries` in the same
   !> bracket; the bisection goes on from there and still converges.
   subroutine test_next_fraction(error)
      type(error_type), allocatable, intent(out) :: error
      type(run_type) :: run
      real(wp) :: x1
      x1 = sqrt(0.1_wp)   ! the first trial point: made to fail alone
      call run_bisection(0.01_wp, 10.0_wp, three_tries, step, &
         x1*(1.0_wp - 1.0e-12_wp), x1*(1.0_wp + 1.0e-12_wp), run)
      call check_converged(error, run, "one failed trial")
      call check(error, run%nfailed == 1, "exactly one failure")
      call check_close(error, run%asked(3), x1, 1.0e-15_wp, what="first trial")
      ! 0.01*(10/0.01)**0.25 = 10**-1.25
      call check_close(error, run%asked(4), 10.0_wp**(-1.25_wp), 1.0e-15_wp, &
         what="replacement at the fraction 0.25")
   end subroutine test_next_fraction

   !> The same mechanism at both ends brackets no change.
   subroutine test_no_solution(error)
      type(error_type), allocatable, intent(out) :: error
      type(run_type) :: run
      call run_bisection(0.5_wp, 2.0_wp, [0.5_wp], step, 1.0_wp, 0.0_wp, run)
      call check(error, run%status == wa_no_solution, "status wa_no_solution")
      call check(error, index(run%msg, "same mechanism") > 0, trim(run%msg))
      call check(error, index(run%msg, "test mechanism") > 0, "message names the caller: "// &
         trim(run%msg))
      call check(error, run%nasked == 2, "asks only the ends")
   end subroutine test_no_solution

   !> Every trial point inside the bracket fails: the caller's status, a message with the
   !> caller's, and the bracket unchanged with its geometric midpoint.
   subroutine test_every_trial_fails(error)
      type(error_type), allocatable, intent(out) :: error
      type(run_type) :: run
      call run_bisection(0.01_wp, 10.0_wp, three_tries, step, &
         0.01_wp, 10.0_wp, run)
      call check(error, run%status == wa_numerical_error, "status of the failing trials")
      call check(error, run%nfailed == 3 .and. run%nasked == 5, "each fraction tried once")
      call check(error, index(run%msg, "fails at every trial mu") > 0 .and. &
         index(run%msg, "synthetic failure") > 0, trim(run%msg))
      call check(error, run%bracket(1) == 0.01_wp .and. run%bracket(2) == 10.0_wp, &
         "bracket unchanged")
      call check_close(error, run%mu_change, sqrt(0.1_wp), 1.0e-15_wp, &
         what="mu_change: the bracket's geometric midpoint")
   end subroutine test_every_trial_fails

   !> Trials fail in (0.3, 0.45) around the change: the bisection stops with the bracket of
   !> computed points around the zone.
   subroutine test_failing_zone(error)
      type(error_type), allocatable, intent(out) :: error
      type(run_type) :: run
      call run_bisection(0.01_wp, 10.0_wp, three_tries, step, &
         0.3_wp, 0.45_wp, run)
      call check(error, run%status == wa_numerical_error, "status of the failing trials")
      call check(error, run%bracket(1) <= 0.3_wp .and. run%bracket(2) >= 0.45_wp, &
         "bracket ends outside the failing zone")
      call check(error, run%bracket(1) > 0.01_wp .and. run%bracket(2) < 10.0_wp, &
         "bracket narrowed before the zone")
      call check(error, index(run%msg, "not located further than") > 0, trim(run%msg))
   end subroutine test_failing_zone

   !> A failure at mu_lo or mu_hi ends the bisection with the caller's status.
   subroutine test_end_fails(error)
      type(error_type), allocatable, intent(out) :: error
      type(run_type) :: run
      call run_bisection(0.01_wp, 10.0_wp, [0.5_wp], step, 0.0_wp, 0.02_wp, run)
      call check(error, run%status == wa_numerical_error .and. run%nasked == 1 .and. &
         index(run%msg, "mu_lo") > 0, "mu_lo fails: "//trim(run%msg))
      call run_bisection(0.01_wp, 10.0_wp, [0.5_wp], step, 5.0_wp, 20.0_wp, run)
      call check(error, run%status == wa_numerical_error .and. run%nasked == 2 .and. &
         index(run%msg, "mu_hi") > 0, "mu_hi fails: "//trim(run%msg))
   end subroutine test_end_fails

   !> A change at mu = 0 with mu_lo = 0: the bracket never narrows relatively, so after 200
   !> halvings (hi = 2**-200) the bisection stops unconverged.
   subroutine test_not_converged(error)
      type(error_type), allocatable, intent(out) :: error
      type(run_type) :: run
      call run_bisection(0.0_wp, 1.0_wp, [0.5_wp], 0.0_wp, 1.0_wp, 0.0_wp, run)
      call check(error, run%status == wa_not_converged, "status wa_not_converged: "// &
         trim(run%msg))
      call check(error, run%nasked == 202, "200 trial points")
      call check(error, run%bracket(1) == 0.0_wp .and. run%bracket(2) == 2.0_wp**(-200), &
         "bracket [0, 2**-200]")
   end subroutine test_not_converged

end module test_mechanism
