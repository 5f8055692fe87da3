!> A small test harness with test-drive's shape: suites are lists of named test
!> procedures; a test reports failure by allocating its `error` argument.
module harness
   use wa_kinds, only: wp
   implicit none
   private

   public :: error_type, unittest_type, new_unittest, test_interface
   public :: testsuite_type, new_testsuite, collect_interface
   public :: check, check_close, run_suite

   !> Allocated only when a test fails; carries the reason.
   type :: error_type
      character(len=:), allocatable :: message
   end type error_type

   abstract interface
      subroutine test_interface(error)
         import :: error_type
         type(error_type), allocatable, intent(out) :: error
      end subroutine test_interface
   end interface

   !> Longest test name. A fixed length, not an allocatable component: gfortran leaks
   !> the allocatable components of array-constructor temporaries such as the
   !> `[new_unittest(...), ...]` of every collect_<suite> (LeakSanitizer, doc/testing.md).
   integer, parameter :: name_len = 64

   type :: unittest_type
      character(len=name_len) :: name = ""
      procedure(test_interface), pointer, nopass :: test => null()
   end type unittest_type

   abstract interface
      !> A suite's tests: each test module's public collect_<suite>.
      subroutine collect_interface(testsuite)
         import :: unittest_type
         type(unittest_type), allocatable, intent(out) :: testsuite(:)
      end subroutine collect_interface
   end interface

   !> A named suite (the table of suites is test/unit/suites.f90). Fixed-length name, as
   !> unittest_type's.
   type :: testsuite_type
      character(len=name_len) :: name = ""
      procedure(collect_interface), pointer, nopass :: collect => null()
   end type testsuite_type

contains

   function new_unittest(name, test) result(self)
      character(len=*), intent(in) :: name
      procedure(test_interface) :: test
      type(unittest_type) :: self
      if (len(name) > name_len) error stop "new_unittest: test name longer than name_len"
      self%name = name
      self%test => test
   end function new_unittest

   function new_testsuite(name, collect) result(self)
      character(len=*), intent(in) :: name
      procedure(collect_interface) :: collect
      type(testsuite_type) :: self
      if (len(name) > name_len) error stop "new_testsuite: suite name longer than name_len"
      self%name = name
      self%collect => collect
   end function new_testsuite

   !> Fail with `message` unless `condition` holds (keeps the first failure).
   subroutine check(error, condition, message)
      type(error_type), allocatable, intent(inout) :: error
      logical, intent(in) :: condition
      character(len=*), intent(in) :: message
      if (allocated(error)) return
      if (.not. condition) then
         allocate (error)
         error%message = message
      end if
   end subroutine check

   !> Fail unless |actual - expected| <= max(rtol*|expected|, atol); prints both on failure.
   subroutine check_close(error, actual, expected, rtol, atol, what)
      type(error_type), allocatable, intent(inout) :: error
      real(wp), intent(in) :: actual, expected, rtol
      real(wp), intent(in), optional :: atol
      character(len=*), intent(in) :: what
      real(wp) :: tol
      character(len=160) :: text
      if (allocated(error)) return
      tol = rtol*abs(expected)
      if (present(atol)) tol = max(tol, atol)
      if (.not. (abs(actual - expected) <= tol)) then
         write (text, '(a,es24.16,a,es24.16,a,es9.2)') " got ", actual, " expected ", &
            expected, " tol ", tol
         allocate (error)
         error%message = what//trim(text)
      end if
   end subroutine check_close

   !> Run every test of a suite (or only `only`), print one line per test;
   !> add the counts to `npass` and `nfail`.
   subroutine run_suite(suite_name, tests, npass, nfail, only)
      character(len=*), intent(in) :: suite_name
      type(unittest_type), intent(in) :: tests(:)
      integer, intent(inout) :: npass, nfail
      character(len=*), intent(in), optional :: only
      type(error_type), allocatable :: error
      integer :: i
      do i = 1, size(tests)
         if (present(only)) then
            if (len_trim(only) > 0 .and. tests(i)%name /= only) cycle
         end if
         call tests(i)%test(error)
         if (allocated(error)) then
            nfail = nfail + 1
            print '(a)', "  FAIL "//suite_name//"/"//trim(tests(i)%name)//": "//error%message
         else
            npass = npass + 1
            print '(a)', "  ok   "//suite_name//"/"//trim(tests(i)%name)
         end if
      end do
   end subroutine run_suite

end module harness
