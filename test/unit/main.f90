!> Test driver: `fpm test unit [suite [test]]` runs the suites of the table in suites.f90
!> (all, or the one named). Prints one line per test and a closing `N passed, N failed`;
!> exits non-zero when anything failed, nothing ran, or the suite named is not in the table.
program tester
   use harness, only: testsuite_type, unittest_type, run_suite
   use suites, only: collect_suites
   implicit none
   type(testsuite_type), allocatable :: testsuites(:)
   type(unittest_type), allocatable :: tests(:)
   character(len=64) :: suite, only
   integer :: npass, nfail, i

   suite = ""; only = ""
   if (command_argument_count() >= 1) call get_command_argument(1, suite)
   if (command_argument_count() >= 2) call get_command_argument(2, only)
   call collect_suites(testsuites)
   if (len_trim(suite) > 0 .and. .not. any(testsuites%name == suite)) then
      print '(a)', "no unit suite '"//trim(suite)//"'; the suites are:"
      do i = 1, size(testsuites)
         print '(2x,a)', trim(testsuites(i)%name)
      end do
      error stop 1
   end if
   npass = 0; nfail = 0
   do i = 1, size(testsuites)
      if (len_trim(suite) > 0 .and. testsuites(i)%name /= suite) cycle
      call testsuites(i)%collect(tests)
      call run_suite(trim(testsuites(i)%name), tests, npass, nfail, only)
   end do
   if (allocated(tests)) deallocate (tests)   ! LeakSanitizer counts what main still holds
   print '(i0,a,i0,a)', npass, " passed, ", nfail, " failed"
   if (nfail > 0 .or. npass == 0) error stop 1

end program tester
