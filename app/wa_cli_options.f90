!> Command-line parsing for the `wavyadhesion` driver (SPEC section 7). Usage errors
!> are returned as a message; the caller prints it and exits with status 2.
module wa_cli_options
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan
   use wavyadhesion, only: wp, model_westergaard, model_jkr, model_dw, model_md
   implicit none
   private

   public :: cli_options, parse_command_line, parse_real_list, model_name

   integer, parameter :: max_values = 100000

   type :: cli_options
      character(len=:), allocatable :: command
      integer :: model = model_dw
      real(wp), allocatable :: alpha(:), mu(:), a_star(:)
      character(len=:), allocatable :: format, output
      logical :: help = .false., version = .false.
      !> SI inputs (NaN when not given)
      real(wp) :: e1, nu1, e2, nu2, estar, period, amplitude, work, peak
   end type cli_options

contains

   !> Read the command line into `opts`; on a usage error, `error` is allocated.
   subroutine parse_command_line(opts, error)
      type(cli_options), intent(out) :: opts
      character(len=:), allocatable, intent(out) :: error
      character(len=:), allocatable :: arg, val
      integer :: i, n

      call reset(opts)
      n = command_argument_count()
      i = 1
      if (n >= 1) then
         arg = argument(1)
         if (arg(1:1) /= "-") then
            opts%command = arg
            i = 2
         end if
      end if
      select case (opts%command)
      case ("point", "branch", "path", "critical")
      case default
         error = "unknown subcommand '"//opts%command//"' (expected point, branch, path or critical)"
         return
      end select
      do while (i <= n)
         arg = argument(i)
         select case (arg)
         case ("--help", "-h"); opts%help = .true.; i = i + 1; cycle
         case ("--version"); opts%version = .true.; i = i + 1; cycle
         end select
         if (i == n) then
            error = "option "//arg//" needs a value"
            return
         end if
         val = argument(i + 1)
         call set_option(opts, arg, val, error)
         if (allocated(error)) return
         i = i + 2
      end do
   end subroutine parse_command_line

   subroutine set_option(opts, arg, val, error)
      type(cli_options), intent(inout) :: opts
      character(len=*), intent(in) :: arg, val
      character(len=:), allocatable, intent(out) :: error
      select case (arg)
      case ("--model")
         select case (val)
         case ("westergaard"); opts%model = model_westergaard
         case ("jkr"); opts%model = model_jkr
         case ("dw"); opts%model = model_dw
         case ("md"); opts%model = model_md
         case default
            error = "--model: '"//val//"' is not one of westergaard, jkr, dw, md"
         end select
      case ("--alpha"); call parse_real_list(val, "--alpha", opts%alpha, error)
      case ("--mu"); call parse_real_list(val, "--mu", opts%mu, error)
      case ("--a-star"); call parse_real_list(val, "--a-star", opts%a_star, error)
      case ("--mu-range"); call parse_mu_range(val, opts%mu, error)
      case ("--format")
         if (val /= "table" .and. val /= "csv") then
            error = "--format: '"//val//"' is not one of table, csv"
         else
            opts%format = val
         end if
      case ("--output"); opts%output = val
      case ("--E1"); call parse_real(val, arg, opts%e1, error)
      case ("--nu1"); call parse_real(val, arg, opts%nu1, error)
      case ("--E2"); call parse_real(val, arg, opts%e2, error)
      case ("--nu2"); call parse_real(val, arg, opts%nu2, error)
      case ("--Estar"); call parse_real(val, arg, opts%estar, error)
      case ("--period"); call parse_real(val, arg, opts%period, error)
      case ("--amplitude"); call parse_real(val, arg, opts%amplitude, error)
      case ("--work-of-adhesion"); call parse_real(val, arg, opts%work, error)
      case ("--peak-stress"); call parse_real(val, arg, opts%peak, error)
      case default
         error = "unknown option '"//arg//"' (see --help)"
      end select
   end subroutine set_option

   !> Comma-separated reals, e.g. "0.1,0.2".
   subroutine parse_real_list(text, name, values, error)
      character(len=*), intent(in) :: text, name
      real(wp), allocatable, intent(out) :: values(:)
      character(len=:), allocatable, intent(out) :: error
      integer :: start, comma, k, nvals
      nvals = count([(text(k:k) == ",", k=1, len(text))]) + 1
      if (nvals > max_values) then
         error = name//": too many values"
         return
      end if
      allocate (values(nvals))
      start = 1
      do k = 1, nvals
         comma = index(text(start:), ",")
         if (comma == 0) comma = len(text) - start + 2
         call parse_real(text(start:start + comma - 2), name, values(k), error)
         if (allocated(error)) return
         start = start + comma
      end do
   end subroutine parse_real_list

   !> LO:HI:N[:log] -> N values of mu from LO to HI, linear or log-spaced.
   subroutine parse_mu_range(text, values, error)
      character(len=*), intent(in) :: text
      real(wp), allocatable, intent(out) :: values(:)
      character(len=:), allocatable, intent(out) :: error
      character(len=:), allocatable :: spec
      real(wp), allocatable :: parts(:)
      logical :: logscale
      integer :: n, i
      spec = text
      logscale = .false.
      if (len(spec) > 4) then
         if (spec(len(spec) - 3:) == ":log") then
            logscale = .true.
            spec = spec(:len(spec) - 4)
         end if
      end if
      do i = 1, len(spec)
         if (spec(i:i) == ":") spec(i:i) = ","
      end do
      call parse_real_list(spec, "--mu-range", parts, error)
      if (allocated(error)) return
      if (size(parts) /= 3) then
         error = "--mu-range: expected LO:HI:N[:log], got '"//text//"'"
         return
      end if
      n = nint(parts(3))
      if (n < 1 .or. abs(parts(3) - n) > 0 .or. n > max_values) then
         error = "--mu-range: N must be an integer in [1, 100000]"
      else if (.not. (parts(1) >= 0.0_wp .and. parts(2) >= parts(1))) then
         error = "--mu-range: need 0 <= LO <= HI"
      else if (logscale .and. parts(1) <= 0.0_wp) then
         error = "--mu-range: LO must be > 0 with :log"
      end if
      if (allocated(error)) return
      allocate (values(n))
      values(1) = parts(1)
      do i = 2, n
         if (logscale) then
            values(i) = parts(1)*(parts(2)/parts(1))**(real(i - 1, wp)/real(n - 1, wp))
         else
            values(i) = parts(1) + (parts(2) - parts(1))*real(i - 1, wp)/real(n - 1, wp)
         end if
      end do
      if (n > 1) values(n) = parts(2)
   end subroutine parse_mu_range

   subroutine parse_real(text, name, x, error)
      character(len=*), intent(in) :: text, name
      real(wp), intent(out) :: x
      character(len=:), allocatable, intent(out) :: error
      integer :: ios
      x = 0.0_wp
      ios = 1
      if (len_trim(text) > 0 .and. verify(trim(text), "0123456789+-.eEdD") == 0) &
         read (text, *, iostat=ios) x
      if (ios /= 0 .or. ieee_is_nan(x)) error = name//": '"//text//"' is not a number"
   end subroutine parse_real

   function model_name(model) result(name)
      integer, intent(in) :: model
      character(len=:), allocatable :: name
      select case (model)
      case (model_westergaard); name = "westergaard"
      case (model_jkr); name = "jkr"
      case (model_dw); name = "dw"
      case default; name = "md"
      end select
   end function model_name

   function argument(i) result(arg)
      integer, intent(in) :: i
      character(len=:), allocatable :: arg
      integer :: length
      call get_command_argument(i, length=length)
      allocate (character(len=length) :: arg)
      call get_command_argument(i, arg)
   end function argument

   subroutine reset(opts)
      type(cli_options), intent(inout) :: opts
      real(wp) :: nan
      nan = ieee_value(nan, ieee_quiet_nan)
      opts%command = "branch"
      opts%format = "table"
      opts%output = ""
      opts%e1 = nan; opts%nu1 = nan; opts%e2 = nan; opts%nu2 = nan; opts%estar = nan
      opts%period = nan; opts%amplitude = nan; opts%work = nan; opts%peak = nan
   end subroutine reset

end module wa_cli_options
