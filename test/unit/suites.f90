!> The one table of the unit-test suites, run in this order by the driver (main.f90) and
!> by the pFUnit bridge (test/pfunit/unit_bridge.f90); test/pfunit/generate.py reads it to
!> write one pFUnit module per suite. A new suite test_<name>.f90 with its public
!> collect_<name> is registered here: its `use` line and its row in `testsuites`.
module suites
   use harness, only: testsuite_type, new_testsuite
   use test_params, only: collect_params
   use test_kernels, only: collect_kernels
   use test_elliptic, only: collect_elliptic
   use test_dw, only: collect_dw
   use test_md, only: collect_md
   use test_reference, only: collect_reference
   use test_branch, only: collect_branch
   use test_robustness, only: collect_robustness
   use test_sweep, only: collect_sweep
   use test_separation, only: collect_separation
   use test_map, only: collect_map
   use test_gappath, only: collect_gappath
   use test_gapcritical, only: collect_gapcritical
   use test_mechanism, only: collect_mechanism
   use test_text, only: collect_text
   use test_bem, only: collect_bem
   implicit none
   private

   public :: collect_suites

contains

   !> Every suite, by name.
   subroutine collect_suites(testsuites)
      type(testsuite_type), allocatable, intent(out) :: testsuites(:)
      testsuites = [ &
         new_testsuite("params", collect_params), &
         new_testsuite("kernels", collect_kernels), &
         new_testsuite("elliptic", collect_elliptic), &
         new_testsuite("dw", collect_dw), &
         new_testsuite("md", collect_md), &
         new_testsuite("reference", collect_reference), &
         new_testsuite("branch", collect_branch), &
         new_testsuite("robustness", collect_robustness), &
         new_testsuite("sweep", collect_sweep), &
         new_testsuite("separation", collect_separation), &
         new_testsuite("map", collect_map), &
         new_testsuite("gappath", collect_gappath), &
         new_testsuite("gapcritical", collect_gapcritical), &
         new_testsuite("mechanism", collect_mechanism), &
         new_testsuite("text", collect_text), &
         new_testsuite("bem", collect_bem)]
   end subroutine collect_suites

end module suites
