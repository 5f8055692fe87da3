!> Progress on standard error for long runs, only when standard error is a terminal
!> (never in CI or when redirected): one line rewritten in place ("\r"), shown once the
!> run has taken about a second, updated at most 10 times a second and erased when the
!> run ends, so that nothing of it stays on the screen.
module wa_cli_progress
   use, intrinsic :: iso_fortran_env, only: error_unit, int64
   implicit none
   private

   public :: progress_type, progress_start, progress_step, progress_status, progress_note, &
      progress_end

   type :: progress_type
      !> standard error is a terminal; the line is on the screen
      logical :: tty = .false., shown = .false.
      integer(int64) :: start = 0, last = 0, rate = 1
      !> the length of the line on the screen (to erase it)
      integer :: width = 0
      character(len=:), allocatable :: what
   end type progress_type

contains

   !> Start timing a run named `what` (e.g. "critical").
   subroutine progress_start(p, what)
      type(progress_type), intent(out) :: p
      character(len=*), intent(in) :: what
      p%tty = isatty(error_unit)                        ! GNU extension
      p%what = what
      call system_clock(p%start, p%rate)
      p%last = p%start
   end subroutine progress_start

   !> `done` of `total` points: shown once a second has passed.
   subroutine progress_step(p, done, total)
      type(progress_type), intent(inout) :: p
      integer, intent(in) :: done, total
      character(len=80) :: text
      write (text, '(i0," of ",i0," points")') done, total
      call progress_status(p, trim(text))
   end subroutine progress_step

   !> A stage of the run (e.g. "locating the mechanism changes"): shown, with the
   !> time, once a second has passed, at most 10 times a second.
   subroutine progress_status(p, text)
      type(progress_type), intent(inout) :: p
      character(len=*), intent(in) :: text
      integer(int64) :: now
      if (.not. p%tty) return
      call system_clock(now)
      if (now - p%start < p%rate) return                 ! the first second: nothing
      if (p%shown .and. now - p%last < p%rate/10) return
      call show(p, p%what//": "//text//", "//seconds(p, now)//" s")
   end subroutine progress_status

   !> A line shown at once (a single library call that cannot report: "map: computing").
   subroutine progress_note(p, text)
      type(progress_type), intent(inout) :: p
      character(len=*), intent(in) :: text
      if (p%tty) call show(p, p%what//": "//text)
   end subroutine progress_note

   !> Erase the line (if it was shown).
   subroutine progress_end(p)
      type(progress_type), intent(inout) :: p
      if (.not. p%shown) return
      write (error_unit, '(a)', advance="no") achar(13)//repeat(" ", p%width)//achar(13)
      flush (error_unit)
      p%shown = .false.
   end subroutine progress_end

   subroutine show(p, line)
      type(progress_type), intent(inout) :: p
      character(len=*), intent(in) :: line
      write (error_unit, '(a)', advance="no") achar(13)//line// &
         repeat(" ", max(0, p%width - len(line)))
      flush (error_unit)
      p%width = max(p%width, len(line))
      p%shown = .true.
      call system_clock(p%last)
   end subroutine show

   function seconds(p, now) result(text)
      type(progress_type), intent(in) :: p
      integer(int64), intent(in) :: now
      character(len=:), allocatable :: text
      character(len=16) :: buf
      write (buf, '(f0.1)') real(now - p%start)/real(p%rate)
      text = trim(buf)
      if (text(1:1) == ".") text = "0"//text
   end function seconds

end module wa_cli_progress
