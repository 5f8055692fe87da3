!> Runs the fpm unit tests of test/unit by suite and name for the pFUnit modules in this
!> folder (pf_<suite>.pf), so that each test's logic stays in test/unit. It looks suites
!> up in the table of test/unit/suites.f90 at run time, so it holds no list of its own.
!> Plain Fortran: it knows nothing of pFUnit.
module unit_bridge
   use harness, only: error_type, unittest_type, testsuite_type
   use suites, only: collect_suites
   implicit none
   private

   public :: unit_test_error, unit_test_count

contains

   !> The tests of one suite; found = .false. (and no tests) for a name not in the table.
   subroutine collect(suite, tests, found)
      character(len=*), intent(in) :: suite
      type(unittest_type), allocatable, intent(out) :: tests(:)
      logical, intent(out) :: found
      type(testsuite_type), allocatable :: testsuites(:)
      integer :: i
      call collect_suites(testsuites)
      do i = 1, size(testsuites)
         if (testsuites(i)%name /= suite) cycle
         call testsuites(i)%collect(tests)
         found = .true.
         return
      end do
      allocate (tests(0))
      found = .false.
   end subroutine collect

   !> Runs test `name` of `suite`: "" when it passed, else the harness's message (or
   !> why it could not run).
   function unit_test_error(suite, name) result(message)
      character(len=*), intent(in) :: suite, name
      character(len=:), allocatable :: message
      type(unittest_type), allocatable :: tests(:)
      type(error_type), allocatable :: error
      logical :: found
      integer :: i

      call collect(suite, tests, found)
      if (.not. found) then
         message = "no unit suite '"//suite//"' in test/unit/suites.f90"
         return
      end if
      do i = 1, size(tests)
         if (tests(i)%name /= name) cycle
         call tests(i)%test(error)
         message = ""
         if (allocated(error)) then
            message = suite//"/"//name//" failed"
            if (allocated(error%message)) message = message//": "//error%message
         end if
         return
      end do
      message = "no test '"//name//"' in unit suite '"//suite//"'"
   end function unit_test_error

   !> How many tests `suite` holds (-1 for a suite not in the table).
   integer function unit_test_count(suite)
      character(len=*), intent(in) :: suite
      type(unittest_type), allocatable :: tests(:)
      logical :: found
      call collect(suite, tests, found)
      unit_test_count = size(tests)
      if (.not. found) unit_test_count = -1
   end function unit_test_count

end module unit_bridge
