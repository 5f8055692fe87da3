!> display: none
!>
!> Where a mechanism (an integer code: how full contact is reached, how contact is lost)
!> changes with mu, by bisection in reverse communication: the caller computes the
!> mechanism at the mu this module asks for, so load control and gap control share the
!> bisection without passing a procedure (an internal procedure as an argument would need
!> an executable stack). Usage:
!>   call bisection_start(bis, mu_lo, mu_hi, tries, "load path")
!>   do
!>      call bisection_next(bis, mu, more); if (.not. more) exit
!>      m = <mechanism at mu>(..., stat, msg)       ! stat /= wa_ok where it cannot be computed
!>      call bisection_tell(bis, m, stat, msg)
!>   end do
!>   call bisection_result(bis, mu_change, status, errmsg, bracket)
!> The bracket [mu_lo, mu_hi] (mechanisms differ at its ends, else wa_no_solution) is
!> narrowed to 1e-10 relative (geometric; arithmetic while the lower end is 0); a trial mu
!> where the mechanism cannot be computed is replaced by the next fraction of the bracket in
!> `tries`; when all of them fail, or after 200 steps, the bisection stops with an error and
!> the interval still known to hold the change.
module wa_mechanism
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_no_solution, wa_not_converged, set_error
   use wa_text, only: real_text
   implicit none
   private

   public :: mechanism_bisection, bisection_start, bisection_next, bisection_tell, &
      bisection_result
   public :: a_point_pull_off

   !> A minimum of P* below this a* from which contact is lost (a fold of case 1 or a
   !> corner at c* = 1/2) counts as a gradual pull-off (load control; gap control likewise for the maximum of
   !> gbar* the retraction jumps from): the contact has shrunk to a point
   !> (doc/theory.md, "Pull-off at a point"). Near a* -> 0, P* - P*(0) behaves like
   !> a*^2 (k1 ln a* + k2), so a case-1 minimum sits at an a* that shrinks exponentially
   !> with mu, its load within ~a*^2 of P*(a* -> 0). Whether it lies above the branch's
   !> first point a_start = 1e-6, where P* is flat to 1e-12, is not decidable in double
   !> precision (the mechanism flickered over 1e-5 relative in mu); at 1e-3 the fold is
   !> placed to ~1e-8 relative, the boundary to ~1e-10 in mu. Likewise a corner minimum
   !> born at a_start (a case-1 piece appearing there) made a sliver of "jump case 2"
   !> 1e-5 wide in mu (DW, alpha 0.31). P_pf stays the load of that minimum.
   real(wp), parameter :: a_point_pull_off = 1.0e-3_wp

   !> What the bisection asks for next
   integer, parameter :: want_lo = 1, want_hi = 2, want_trial = 3, finished = 4
   integer, parameter :: max_steps = 200
   real(wp), parameter :: rel_width = 1.0e-10_wp

   !> The bisection's state (no procedure, no module state: one per call, thread-safe).
   type :: mechanism_bisection
      private
      real(wp) :: lo = 0.0_wp, hi = 0.0_wp, x = 0.0_wp
      real(wp), allocatable :: tries(:)
      character(len=:), allocatable :: what
      integer :: m_lo = -1, phase = finished, step = 0, k = 0
      integer :: status = wa_ok
      character(len=:), allocatable :: msg
   end type mechanism_bisection

contains

   !> Start on [mu_lo, mu_hi]; `what` names the computation in the messages.
   pure subroutine bisection_start(bis, mu_lo, mu_hi, tries, what)
      type(mechanism_bisection), intent(out) :: bis
      real(wp), intent(in) :: mu_lo, mu_hi, tries(:)
      character(len=*), intent(in) :: what
      bis%lo = mu_lo
      bis%hi = mu_hi
      bis%tries = tries
      bis%what = what
      bis%phase = want_lo
   end subroutine bisection_start

   !> The mu at which the caller must compute the mechanism next, or more = .false. when
   !> the bisection has ended.
   pure subroutine bisection_next(bis, mu, more)
      type(mechanism_bisection), intent(in) :: bis
      real(wp), intent(out) :: mu
      logical, intent(out) :: more
      more = bis%phase /= finished
      select case (bis%phase)
      case (want_lo);  mu = bis%lo
      case (want_hi);  mu = bis%hi
      case default;    mu = bis%x
      end select
   end subroutine bisection_next

   !> The mechanism at the mu of bisection_next (stat /= wa_ok, with msg, where it
   !> could not be computed).
   pure subroutine bisection_tell(bis, mechanism, stat, msg)
      type(mechanism_bisection), intent(inout) :: bis
      integer, intent(in) :: mechanism, stat
      character(len=*), intent(in) :: msg
      select case (bis%phase)
      case (want_lo)
         if (stat /= wa_ok) then
            call fail(bis, stat, "mechanism change: mu_lo = "//real_text(bis%lo)//": "// &
               trim(msg))
         else
            bis%m_lo = mechanism
            bis%phase = want_hi
         end if
      case (want_hi)
         if (stat /= wa_ok) then
            call fail(bis, stat, "mechanism change: mu_hi = "//real_text(bis%hi)//": "// &
               trim(msg))
         else if (mechanism == bis%m_lo) then   ! no change (or an even number) in the bracket
            call fail(bis, wa_no_solution, "mechanism change: the "//bis%what//" has the "// &
               "same mechanism at mu_lo and mu_hi, so no change is bracketed")
         else
            call next_step(bis)
         end if
      case (want_trial)
         if (stat == wa_ok) then
            if (mechanism == bis%m_lo) then
               bis%lo = bis%x
            else
               bis%hi = bis%x
            end if
            call next_step(bis)
         else if (bis%k == size(bis%tries)) then
            call fail(bis, stat, "mechanism change not located further than ["// &
               real_text(bis%lo)//", "//real_text(bis%hi)//"]: the "//bis%what// &
               " fails at every trial mu inside ("//trim(msg)//")")
         else
            call next_trial(bis, bis%k + 1)
         end if
      end select
   end subroutine bisection_tell

   !> The result: mu_change, the midpoint of the bracket still known to hold the change
   !> (`bracket`, also on failure), and the status with its message.
   pure subroutine bisection_result(bis, mu_change, status, errmsg, bracket)
      type(mechanism_bisection), intent(in) :: bis
      real(wp), intent(out) :: mu_change
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), intent(out), optional :: bracket(2)
      status = wa_ok
      if (bis%status /= wa_ok) call set_error(bis%status, bis%msg, status, errmsg)
      mu_change = inside(bis%lo, bis%hi, 0.5_wp)
      if (present(bracket)) bracket = [bis%lo, bis%hi]
   end subroutine bisection_result

   !> One bisection step: stop when the bracket is narrow enough, else try its first fraction.
   pure subroutine next_step(bis)
      type(mechanism_bisection), intent(inout) :: bis
      bis%step = bis%step + 1
      if (.not. (bis%hi - bis%lo > rel_width*bis%hi)) then
         bis%phase = finished
      else if (bis%step > max_steps) then
         call fail(bis, wa_not_converged, "mechanism change: no convergence in 200 "// &
            "bisection steps")
      else
         call next_trial(bis, 1)
      end if
   end subroutine next_step

   !> Ask for the k-th fraction of the bracket; stop when no representable point is left.
   pure subroutine next_trial(bis, k)
      type(mechanism_bisection), intent(inout) :: bis
      integer, intent(in) :: k
      bis%k = k
      bis%x = inside(bis%lo, bis%hi, bis%tries(k))
      if (bis%x > bis%lo .and. bis%x < bis%hi) then
         bis%phase = want_trial
      else
         bis%phase = finished
      end if
   end subroutine next_trial

   pure subroutine fail(bis, stat, text)
      type(mechanism_bisection), intent(inout) :: bis
      integer, intent(in) :: stat
      character(len=*), intent(in) :: text
      bis%status = stat
      bis%msg = text
      bis%phase = finished
   end subroutine fail

   !> The point at fraction f of [a, b]: geometric when a > 0, else arithmetic.
   pure real(wp) function inside(a, b, f)
      real(wp), intent(in) :: a, b, f
      if (a > 0.0_wp) then
         inside = a*(b/a)**f
      else
         inside = a + f*(b - a)
      end if
   end function inside

end module wa_mechanism
