!> Where the CLI's table goes: standard output or `--output FILE`, written through C
!> stdio so that every write error is seen (gfortran's own units do not report ENOSPC:
!> `--output /dev/full` would "succeed"). A regular FILE (or a missing one) is written to
!> a temporary file in the same directory, which is renamed over FILE only when the whole
!> table was written and closed: an existing FILE is never damaged and no empty file is
!> left behind when a run fails. Anything else (a device such as /dev/null or /dev/full,
!> a FIFO) is written directly. SIGINT, SIGTERM and SIGHUP remove the temporary file.
module wa_cli_output
   use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_char, &
      c_null_char, c_int, c_size_t, c_f_pointer, c_funptr, c_funloc
   implicit none
   private

   public :: sink_type, open_sink, put_line, close_sink, discard_sink

   !> One output destination.
   type :: sink_type
      !> C FILE * (C_NULL_PTR when not open)
      type(c_ptr) :: file = c_null_ptr
      !> What the user named ("" = standard output), for messages
      character(len=:), allocatable :: target
      !> The file to rename over (resolved through symbolic links), "" when direct
      character(len=:), allocatable :: final
      !> The temporary file written instead of `final`, "" when direct
      character(len=:), allocatable :: temp
      !> A write already failed (its message has been printed)
      logical :: failed = .false.
   end type sink_type

   integer, parameter :: s_ifmt = int(o'170000'), s_ifreg = int(o'100000')
   !> POSIX signal numbers (the same on Linux and macOS)
   integer(c_int), parameter :: sigint = 2, sigterm = 15, sighup = 1
   integer, parameter :: path_max = 4096

   !> The temporary file to unlink if SIGINT/SIGTERM/SIGHUP ends the program (NUL-
   !> terminated; empty when none). The one piece of program-wide state of the driver: a
   !> signal handler can reach nothing else. Not part of the library.
   character(kind=c_char, len=path_max), save, volatile :: pending_temp = c_null_char

   interface
      function c_fopen(path, mode) result(file) bind(C, name="fopen")
         import :: c_ptr, c_char
         character(kind=c_char), intent(in) :: path(*), mode(*)
         type(c_ptr) :: file
      end function c_fopen
      function c_fdopen(fd, mode) result(file) bind(C, name="fdopen")
         import :: c_ptr, c_char, c_int
         integer(c_int), value :: fd
         character(kind=c_char), intent(in) :: mode(*)
         type(c_ptr) :: file
      end function c_fdopen
      function c_fwrite(buf, size, n, file) result(written) bind(C, name="fwrite")
         import :: c_ptr, c_char, c_size_t
         character(kind=c_char), intent(in) :: buf(*)
         integer(c_size_t), value :: size, n
         type(c_ptr), value :: file
         integer(c_size_t) :: written
      end function c_fwrite
      function c_fflush(file) result(status) bind(C, name="fflush")
         import :: c_ptr, c_int
         type(c_ptr), value :: file
         integer(c_int) :: status
      end function c_fflush
      function c_fclose(file) result(status) bind(C, name="fclose")
         import :: c_ptr, c_int
         type(c_ptr), value :: file
         integer(c_int) :: status
      end function c_fclose
      function c_rename(old, new) result(status) bind(C, name="rename")
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: old(*), new(*)
         integer(c_int) :: status
      end function c_rename
      function c_remove(path) result(status) bind(C, name="remove")
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: status
      end function c_remove
      subroutine c_perror(text) bind(C, name="perror")
         import :: c_char
         character(kind=c_char), intent(in) :: text(*)
      end subroutine c_perror
      function c_getpid() result(pid) bind(C, name="getpid")
         import :: c_int
         integer(c_int) :: pid
      end function c_getpid
      function c_realpath(path, resolved) result(out) bind(C, name="realpath")
         import :: c_ptr, c_char
         character(kind=c_char), intent(in) :: path(*)
         type(c_ptr), value :: resolved
         type(c_ptr) :: out
      end function c_realpath
      function c_strlen(s) result(n) bind(C, name="strlen")
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s
         integer(c_size_t) :: n
      end function c_strlen
      function c_chmod(path, mode) result(status) bind(C, name="chmod")
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
         integer(c_int) :: status
      end function c_chmod
      function c_signal(signum, handler) result(previous) bind(C, name="signal")
         import :: c_int, c_funptr
         integer(c_int), value :: signum
         type(c_funptr), value :: handler
         type(c_funptr) :: previous
      end function c_signal
      function c_unlink(path) result(status) bind(C, name="unlink")
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: status
      end function c_unlink
      subroutine c_exit_now(status) bind(C, name="_exit")
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit_now
      subroutine c_free(p) bind(C, name="free")
         import :: c_ptr
         type(c_ptr), value :: p
      end subroutine c_free
   end interface

contains

   !> Open standard output (path = "") or the temporary file for `path`. On failure
   !> the reason has been printed to standard error and `ok` is false; `no_directory`
   !> tells a path whose directory does not exist (a usage error) from one that cannot
   !> be written (a write error: /proc/version, a read-only directory, ...).
   subroutine open_sink(sink, path, ok, no_directory)
      type(sink_type), intent(out) :: sink
      character(len=*), intent(in) :: path
      logical, intent(out) :: ok
      logical, intent(out), optional :: no_directory
      intrinsic :: stat                                  ! GNU extension, as isatty in main
      integer :: values(13), status, k
      character(len=12) :: pid, attempt

      if (present(no_directory)) no_directory = .false.
      sink%target = path
      sink%final = ""
      sink%temp = ""
      if (len(path) == 0) then
         sink%file = c_fdopen(1_c_int, "w"//c_null_char)
         ok = c_associated(sink%file)
         if (.not. ok) call c_perror("wavyadhesion: cannot write to standard output"//c_null_char)
         return
      end if
      call stat(path, values, status)                    ! follows symbolic links
      if (status == 0) then
         if (iand(values(3), s_ifmt) /= s_ifreg) then    ! device, FIFO, directory: direct
            sink%file = c_fopen(path//c_null_char, "w"//c_null_char)
            ok = c_associated(sink%file)
            if (.not. ok) call c_perror("wavyadhesion: --output: cannot open '"//path// &
               "' for writing"//c_null_char)
            return
         end if
         sink%final = resolved(path)
      else
         sink%final = path
      end if
      ! The handlers are in place, and the name published, before the file exists: a
      ! signal at any moment removes whatever temporary file there is (no window).
      call catch_signals()
      write (pid, '(i0)') c_getpid()
      do k = 0, 9                                        ! "x": never reuse an existing name
         write (attempt, '(i0)') k
         sink%temp = directory(sink%final)//"."//base_name(sink%final)//".tmp-"// &
            trim(pid)//"-"//trim(attempt)
         call publish_temp(sink%temp)
         sink%file = c_fopen(sink%temp//c_null_char, "wx"//c_null_char)
         if (c_associated(sink%file)) exit
         pending_temp(1:1) = c_null_char                 ! not ours: never remove it
      end do
      ok = c_associated(sink%file)
      if (.not. ok .and. present(no_directory)) then
         call stat(directory(sink%final)//".", values, status)
         no_directory = status /= 0
      end if
      if (ok .and. status == 0) &                        ! keep FILE's permission bits
         status = c_chmod(sink%temp//c_null_char, int(iand(values(3), int(o'7777')), c_int))
      if (.not. ok) call c_perror("wavyadhesion: --output: cannot create a file in the "// &
         "directory of '"//path//"'"//c_null_char)
   end subroutine open_sink

   !> Write one line. The first failure prints its reason; later lines are skipped.
   subroutine put_line(sink, line)
      type(sink_type), intent(inout) :: sink
      character(len=*), intent(in) :: line
      character(len=:), allocatable :: text
      if (sink%failed) return
      text = line//new_line("a")
      if (c_fwrite(text, 1_c_size_t, int(len(text), c_size_t), sink%file) /= len(text)) &
         call write_failed(sink)
   end subroutine put_line

   !> Flush and close (standard output: flush only), then rename the temporary file over
   !> the target. ok is false (reason printed, temporary file removed) if anything failed.
   subroutine close_sink(sink, ok)
      type(sink_type), intent(inout) :: sink
      logical, intent(out) :: ok
      integer(c_int) :: status
      if (.not. sink%failed) then
         if (c_fflush(sink%file) /= 0) call write_failed(sink)
      end if
      if (len(sink%target) > 0) then
         status = c_fclose(sink%file)
         if (status /= 0 .and. .not. sink%failed) call write_failed(sink)
         sink%file = c_null_ptr
      end if
      ok = .not. sink%failed
      if (len(sink%temp) == 0) return
      pending_temp = c_null_char
      if (ok) then
         if (c_rename(sink%temp//c_null_char, sink%final//c_null_char) /= 0) then
            call c_perror("wavyadhesion: --output: cannot rename '"//sink%temp//"' to '"// &
               sink%final//"'"//c_null_char)
            ok = .false.
         end if
      end if
      if (.not. ok) status = c_remove(sink%temp//c_null_char)
   end subroutine close_sink

   !> Give up: close, and remove the temporary file (the target is left as it was).
   subroutine discard_sink(sink)
      type(sink_type), intent(inout) :: sink
      integer(c_int) :: status
      if (.not. c_associated(sink%file)) return
      if (len(sink%target) == 0) then
         status = c_fflush(sink%file)
         return
      end if
      status = c_fclose(sink%file)
      sink%file = c_null_ptr
      pending_temp = c_null_char
      if (len(sink%temp) > 0) status = c_remove(sink%temp//c_null_char)
   end subroutine discard_sink

   !> Catch SIGINT, SIGTERM and SIGHUP: a run stopped by Ctrl-C or kill removes its
   !> temporary file (the target stays as it was) and exits with 128 + signal.
   subroutine catch_signals()
      type(c_funptr) :: previous
      previous = c_signal(sigint, c_funloc(on_signal))
      previous = c_signal(sigterm, c_funloc(on_signal))
      previous = c_signal(sighup, c_funloc(on_signal))
   end subroutine catch_signals

   !> Make `temp` the file the signal handler removes. Its first byte is stored last, so
   !> the handler sees either no name or the whole name, never part of one.
   subroutine publish_temp(temp)
      character(len=*), intent(in) :: temp
      pending_temp(1:1) = c_null_char
      if (len(temp) < 1 .or. len(temp) >= path_max) return
      pending_temp(2:) = temp(2:)//c_null_char
      pending_temp(1:1) = temp(1:1)
   end subroutine publish_temp

   !> Signal handler: unlink the temporary file and exit with 128 + signal (only
   !> async-signal-safe calls: unlink, _exit).
   subroutine on_signal(signum) bind(C)
      integer(c_int), value :: signum
      integer(c_int) :: status
      if (pending_temp(1:1) /= c_null_char) status = c_unlink(pending_temp)
      call c_exit_now(128_c_int + signum)
   end subroutine on_signal

   subroutine write_failed(sink)
      type(sink_type), intent(inout) :: sink
      sink%failed = .true.
      if (len(sink%target) == 0) then
         call c_perror("wavyadhesion: cannot write the table to standard output"//c_null_char)
      else
         call c_perror("wavyadhesion: --output: cannot write the table to '"//sink%target// &
            "'"//c_null_char)
      end if
   end subroutine write_failed

   !> The path with symbolic links resolved (the path itself when that fails).
   function resolved(path) result(real_path)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: real_path
      type(c_ptr) :: p
      character(kind=c_char), pointer :: chars(:)
      integer :: n, i
      p = c_realpath(path//c_null_char, c_null_ptr)
      if (.not. c_associated(p)) then
         real_path = path
         return
      end if
      n = int(c_strlen(p))
      call c_f_pointer(p, chars, [n])
      allocate (character(len=n) :: real_path)
      do i = 1, n
         real_path(i:i) = chars(i)
      end do
      call c_free(p)
   end function resolved

   pure function directory(path) result(dir)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: dir
      dir = path(:index(path, "/", back=.true.))
   end function directory

   pure function base_name(path) result(base)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: base
      base = path(index(path, "/", back=.true.) + 1:)
   end function base_name

end module wa_cli_output
