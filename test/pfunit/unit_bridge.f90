!> Runs the fpm unit tests of test/unit by suite and name for the pFUnit modules in this
!> folder (pf_<suite>.pf), so that each test's logic stays in test/unit. Plain Fortran:
!> it knows nothing of pFUnit.
module unit_bridge
   use harness, only: error_type, unittest_type
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
   implicit none
   private

   public :: unit_test_error, unit_test_count

contains

   !> The tests of one suite (none for an unknown suite name).
   subroutine collect(suite, tests)
      character(len=*), intent(in) :: suite
      type(unittest_type), allocatable, intent(out) :: tests(:)
      select case (suite)
      case ("params"); call collect_params(tests)
      case ("kernels"); call collect_kernels(tests)
      case ("elliptic"); call collect_elliptic(tests)
      case ("dw"); call collect_dw(tests)
      case ("md"); call collect_md(tests)
      case ("reference"); call collect_reference(tests)
      case ("branch"); call collect_branch(tests)
      case ("robustness"); call collect_robustness(tests)
      case ("sweep"); call collect_sweep(tests)
      case ("separation"); call collect_separation(tests)
      case ("map"); call collect_map(tests)
      case ("gappath"); call collect_gappath(tests)
      case default; allocate (tests(0))
      end select
   end subroutine collect

   !> Runs test `name` of `suite`: "" when it passed, else the harness's message (or
   !> why it could not run).
   function unit_test_error(suite, name) result(message)
      character(len=*), intent(in) :: suite, name
      character(len=:), allocatable :: message
      type(unittest_type), allocatable :: tests(:)
      type(error_type), allocatable :: error
      integer :: i

      call collect(suite, tests)
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

   !> How many tests `suite` holds.
   integer function unit_test_count(suite)
      character(len=*), intent(in) :: suite
      type(unittest_type), allocatable :: tests(:)
      call collect(suite, tests)
      unit_test_count = size(tests)
   end function unit_test_count

end module unit_bridge
