!> Test driver: `fpm test unit [suite [test]]`. Prints one line per test and a closing
!> `N passed, N failed`; exits non-zero when anything failed.
program tester
   use harness, only: unittest_type, run_suite
   use test_params, only: collect_params
   use test_kernels, only: collect_kernels
   use test_elliptic, only: collect_elliptic
   use test_dw, only: collect_dw
   use test_md, only: collect_md
   use test_reference, only: collect_reference
   use test_branch, only: collect_branch
   use test_sweep, only: collect_sweep
   use test_robustness, only: collect_robustness
   use test_separation, only: collect_separation
   use test_map, only: collect_map
   use test_gappath, only: collect_gappath
   use test_gapcritical, only: collect_gapcritical
   use test_bem, only: collect_bem
   implicit none
   type(unittest_type), allocatable :: tests(:)
   character(len=64) :: suite, only
   integer :: npass, nfail

   suite = ""; only = ""
   if (command_argument_count() >= 1) call get_command_argument(1, suite)
   if (command_argument_count() >= 2) call get_command_argument(2, only)
   npass = 0; nfail = 0
   if (wanted("params")) then
      call collect_params(tests); call run_suite("params", tests, npass, nfail, only)
   end if
   if (wanted("kernels")) then
      call collect_kernels(tests); call run_suite("kernels", tests, npass, nfail, only)
   end if
   if (wanted("elliptic")) then
      call collect_elliptic(tests); call run_suite("elliptic", tests, npass, nfail, only)
   end if
   if (wanted("dw")) then
      call collect_dw(tests); call run_suite("dw", tests, npass, nfail, only)
   end if
   if (wanted("md")) then
      call collect_md(tests); call run_suite("md", tests, npass, nfail, only)
   end if
   if (wanted("reference")) then
      call collect_reference(tests); call run_suite("reference", tests, npass, nfail, only)
   end if
   if (wanted("branch")) then
      call collect_branch(tests); call run_suite("branch", tests, npass, nfail, only)
   end if
   if (wanted("robustness")) then
      call collect_robustness(tests); call run_suite("robustness", tests, npass, nfail, only)
   end if
   if (wanted("sweep")) then
      call collect_sweep(tests); call run_suite("sweep", tests, npass, nfail, only)
   end if
   if (wanted("separation")) then
      call collect_separation(tests); call run_suite("separation", tests, npass, nfail, only)
   end if
   if (wanted("map")) then
      call collect_map(tests); call run_suite("map", tests, npass, nfail, only)
   end if
   if (wanted("gappath")) then
      call collect_gappath(tests); call run_suite("gappath", tests, npass, nfail, only)
   end if
   if (wanted("gapcritical")) then
      call collect_gapcritical(tests); call run_suite("gapcritical", tests, npass, nfail, only)
   end if
   if (wanted("bem")) then
      call collect_bem(tests); call run_suite("bem", tests, npass, nfail, only)
   end if
   if (allocated(tests)) deallocate (tests)   ! LeakSanitizer counts what main still holds
   print '(i0,a,i0,a)', npass, " passed, ", nfail, " failed"
   if (nfail > 0 .or. npass == 0) error stop 1

contains

   logical function wanted(name)
      character(len=*), intent(in) :: name
      wanted = len_trim(suite) == 0 .or. trim(suite) == name
   end function wanted

end program tester
