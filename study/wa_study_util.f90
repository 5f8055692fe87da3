!> Small utilities of the accuracy/performance study: clock, medians, the error measure
!> of the accuracy targets (doc/accuracy-performance.md), and the reader of the mpmath reference tables (test/data/*.txt,
!> study/data/*.txt: alpha mu a_star c_star gap P_star zone_case).
module wa_study_util
   use, intrinsic :: iso_fortran_env, only: int64
   use wa_kinds, only: wp
   implicit none
   private

   public :: seconds, median, sort_real, spec_error, ref_table, read_table, point_set
   public :: ref_states_of, to_repository_root

   !> The rows of one reference table.
   type :: ref_table
      integer :: n = 0
      real(wp), allocatable :: alpha(:), mu(:), a_star(:), c_star(:), gap(:), p_star(:)
      integer, allocatable :: zone_case(:)
   end type ref_table

   !> Distinct (alpha, mu, a*) points with the index range of their rows in a ref_table.
   type :: point_set
      integer :: n = 0
      real(wp), allocatable :: alpha(:), mu(:), a_star(:)
      integer, allocatable :: first(:), last(:)
   end type point_set

contains

   !> The study reads and writes paths relative to the repository's root (test/data,
   !> study/data, build/study): run from study/ (where its fpm package is), it moves there
   !> first (GNU chdir).
   subroutine to_repository_root()
      intrinsic :: chdir
      logical :: here, above
      inquire (file="test/data/dw.txt", exist=here)
      inquire (file="../test/data/dw.txt", exist=above)
      if (.not. here .and. above) call chdir("..")
   end subroutine to_repository_root

   !> Wall-clock seconds (system_clock, int64: ns resolution here).
   real(wp) function seconds()
      integer(int64) :: count, rate
      call system_clock(count, rate)
      seconds = real(count, wp)/real(rate, wp)
   end function seconds

   !> Median of x (x unchanged).
   real(wp) function median(x)
      real(wp), intent(in) :: x(:)
      real(wp) :: y(size(x))
      if (size(x) == 0) then
         median = 0.0_wp
         return
      end if
      y = x
      call sort_real(y)
      median = y((size(y) + 1)/2)
   end function median

   !> Insertion sort (the sets here have at most a few thousand elements).
   subroutine sort_real(x)
      real(wp), intent(inout) :: x(:)
      real(wp) :: v
      integer :: i, j
      do i = 2, size(x)
         v = x(i)
         j = i - 1
         do while (j >= 1)
            if (x(j) <= v) exit
            x(j + 1) = x(j)
            j = j - 1
         end do
         x(j + 1) = v
      end do
   end subroutine sort_real

   !> The accuracy targets' error of a state: the larger of the relative error in c* and the
   !> error in P* (relative, absolute where |P*_ref| < 1e-3). NaN counts as huge.
   elemental real(wp) function spec_error(c, p, c_ref, p_ref) result(e)
      real(wp), intent(in) :: c, p, c_ref, p_ref
      real(wp) :: ep
      if (abs(p_ref) < 1.0e-3_wp) then
         ep = abs(p - p_ref)
      else
         ep = abs(p - p_ref)/abs(p_ref)
      end if
      e = max(abs(c - c_ref)/abs(c_ref), ep)
      if (.not. (e == e)) e = huge(1.0_wp)
   end function spec_error

   !> Read a reference table; comment lines start with '#'.
   subroutine read_table(path, t)
      character(len=*), intent(in) :: path
      type(ref_table), intent(out) :: t
      character(len=512) :: line
      integer :: u, ios, n
      real(wp) :: v(6)
      integer :: zc
      open (newunit=u, file=path, status="old", action="read")
      n = 0
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         n = n + 1
      end do
      allocate (t%alpha(n), t%mu(n), t%a_star(n), t%c_star(n), t%gap(n), t%p_star(n), &
         t%zone_case(n))
      rewind (u)
      t%n = 0
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         read (line, *) v, zc
         t%n = t%n + 1
         t%alpha(t%n) = v(1); t%mu(t%n) = v(2); t%a_star(t%n) = v(3)
         t%c_star(t%n) = v(4); t%gap(t%n) = v(5); t%p_star(t%n) = v(6)
         t%zone_case(t%n) = zc
      end do
      close (u)
   end subroutine read_table

   !> The distinct points of a table (rows of one point are consecutive).
   function ref_states_of(t) result(ps)
      type(ref_table), intent(in) :: t
      type(point_set) :: ps
      integer :: i
      allocate (ps%alpha(t%n), ps%mu(t%n), ps%a_star(t%n), ps%first(t%n), ps%last(t%n))
      ps%n = 0
      do i = 1, t%n
         if (i > 1) then
            if (t%alpha(i) == t%alpha(i - 1) .and. t%mu(i) == t%mu(i - 1) .and. &
               t%a_star(i) == t%a_star(i - 1)) then
               ps%last(ps%n) = i
               cycle
            end if
         end if
         ps%n = ps%n + 1
         ps%alpha(ps%n) = t%alpha(i)
         ps%mu(ps%n) = t%mu(i)
         ps%a_star(ps%n) = t%a_star(i)
         ps%first(ps%n) = i
         ps%last(ps%n) = i
      end do
   end function ref_states_of

end module wa_study_util
