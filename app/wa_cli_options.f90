!> Command-line parsing for the `wavyadhesion` driver (doc/user-guide.md, "Command line"). Usage errors
!> are returned as a message; the caller prints it and exits with status 2.
module wa_cli_options
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
      ieee_quiet_nan
   use wa_kinds, only: wp
   use wavyadhesion, only: model_westergaard, model_jkr, model_dw, model_md
   implicit none
   private

   public :: cli_options, parse_command_line, parse_real_list, model_name, given, si_given, &
      option_message, is_subcommand, model_lj

   !> --model lj: the smooth (Lennard-Jones) model, run by wa_cli_lj (the C face's
   !> WA_MODEL_LJ)
   integer, parameter :: model_lj = 4

   integer, parameter :: max_values = 100000
   !> The SI options: moduli (1-4), Estar (5), geometry and adhesion (6-9).
   character(len=*), parameter :: si_names(9) = [character(len=18) :: "--E1", "--nu1", &
      "--E2", "--nu2", "--Estar", "--period", "--amplitude", "--work-of-adhesion", &
      "--peak-stress"]

   type :: cli_options
      character(len=:), allocatable :: command
      integer :: model = model_dw
      real(wp), allocatable :: alpha(:), mu(:), a_star(:)
      !> profile: the state's c* (not allocated: the principal state) and the points
      real(wp), allocatable :: c_star(:)
      !> profile: the points; --model lj: the grid points per period
      integer :: n_points = 201
      !> --model lj: the file of profile samples (not allocated: the sinusoid)
      character(len=:), allocatable :: profile_file
      !> gaplaw: the mean gaps (--gbar-range LO:HI:N)
      real(wp), allocatable :: gbar(:)
      character(len=:), allocatable :: format, output
      !> path: "load" (default) or "gap" (mean-gap control)
      character(len=:), allocatable :: control
      !> --units: "reduced" (default) or "si" (SI columns added; needs SI input)
      character(len=:), allocatable :: units
      logical :: help = .false., version = .false.
      !> The subcommand whose help is asked for ("" = the global help): `help SUB`,
      !> `SUB --help`
      character(len=:), allocatable :: help_topic
      !> SI inputs (NaN when not given)
      real(wp) :: e1, nu1, e2, nu2, estar, period, amplitude, work, peak
      !> The options given, as "|--alpha|--mu|" (each option may be given once)
      character(len=:), allocatable :: given
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
         if (arg == "help") then
            call parse_help(opts, n, error)
            return
         end if
         if (arg(1:1) /= "-") then
            opts%command = arg
            opts%help_topic = arg
            i = 2
         end if
      end if
      if (.not. is_subcommand(opts%command)) then
         error = "unknown subcommand '"//opts%command//"' (expected point, branch, path, "// &
            "critical, map, profile or gaplaw)"
         return
      end if
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
         if (given(opts, arg)) then
            error = "option "//arg//" is given twice (give each option once)"
            return
         end if
         call set_option(opts, arg, val, error)
         if (allocated(error)) return
         opts%given = opts%given//arg//"|"
         i = i + 2
      end do
      if (.not. opts%help) call check_combination(opts, error)   ! `gaplaw --help` is help
   end subroutine parse_command_line

   !> `wavyadhesion help [SUBCOMMAND]`: the global help or the subcommand's.
   subroutine parse_help(opts, n, error)
      type(cli_options), intent(inout) :: opts
      integer, intent(in) :: n
      character(len=:), allocatable, intent(out) :: error
      opts%help = .true.
      if (n == 1) return
      opts%help_topic = argument(2)
      if (n > 2) then
         error = "help takes one subcommand (help SUBCOMMAND)"
      else if (.not. is_subcommand(opts%help_topic)) then
         error = "help: unknown subcommand '"//opts%help_topic//"' (expected point, "// &
            "branch, path, critical, map, profile or gaplaw)"
      end if
   end subroutine parse_help

   pure logical function is_subcommand(name)
      character(len=*), intent(in) :: name
      select case (name)
      case ("point", "branch", "path", "critical", "map", "profile", "gaplaw")
         is_subcommand = .true.
      case default
         is_subcommand = .false.
      end select
   end function is_subcommand

   !> True when --control was given with value `value`.
   pure logical function control_is(opts, value)
      type(cli_options), intent(in) :: opts
      character(len=*), intent(in) :: value
      control_is = .false.
      if (allocated(opts%control)) control_is = opts%control == value
   end function control_is

   !> True when option `name` (e.g. "--alpha") was given.
   pure logical function given(opts, name)
      type(cli_options), intent(in) :: opts
      character(len=*), intent(in) :: name
      given = index(opts%given, "|"//name//"|") > 0
   end function given

   !> True when any SI option was given.
   pure logical function si_given(opts)
      type(cli_options), intent(in) :: opts
      integer :: k
      si_given = .false.
      do k = 1, size(si_names)
         si_given = si_given .or. given(opts, trim(si_names(k)))
      end do
   end function si_given

   !> Options that contradict each other, are incomplete, or do not apply to the
   !> subcommand: a usage error rather than a silent choice.
   subroutine check_combination(opts, error)
      type(cli_options), intent(in) :: opts
      character(len=:), allocatable, intent(out) :: error
      character(len=:), allocatable :: missing
      integer :: k
      if (given(opts, "--mu") .and. given(opts, "--mu-range")) then
         error = "--mu and --mu-range cannot be used together (give one)"
      else if (given(opts, "--mu-range") .and. opts%command /= "critical" .and. &
         opts%command /= "map") then
         error = "--mu-range is only for the critical and map subcommands"
      else if (given(opts, "--alpha-range") .and. opts%command /= "map") then
         error = "--alpha-range is only for the map subcommand"
      else if (given(opts, "--alpha") .and. given(opts, "--alpha-range")) then
         error = "--alpha and --alpha-range cannot be used together (give one)"
      else if (opts%command == "map" .and. (given(opts, "--mu") .or. si_given(opts))) then
         error = "map covers a range of mu: use --mu-range LO:HI:N:log, not --mu or SI input"
      else if (given(opts, "--a-star") .and. opts%command /= "point" .and. &
            opts%command /= "profile") then
         error = "--a-star is only for the point and profile subcommands"
      else if ((given(opts, "--c-star") .and. opts%command /= "profile") .or. &
            (given(opts, "--n") .and. opts%command /= "profile" .and. opts%model /= model_lj)) then
         error = "--c-star and --n are only for the profile subcommand (--n also for "// &
            "--model lj: the grid)"
      else if (given(opts, "--profile-file") .and. opts%model /= model_lj) then
         error = "--profile-file is only for --model lj"
      else if (opts%model == model_lj .and. opts%command == "point") then
         error = "point --model lj is not available: a state at given a* is drawn by "// &
            "'profile --model lj --a-star X' (the traced state with a* nearest X), the curve "// &
            "P*(a*) by 'branch --model lj'"
      else if (opts%model == model_lj .and. opts%command == "map") then
         error = "map --model lj is not available: the adhesion map is the mechanism map of "// &
            "--model dw or md; LJ's critical values over a grid: 'critical --model lj "// &
            "--alpha A[,A...] --mu-range LO:HI:N'"
      else if (opts%model == model_lj .and. opts%command == "gaplaw") then
         error = "gaplaw --model lj is not available: LJ's gap law is its traced curve "// &
            "P*(gbar*), 'branch --model lj' (columns P_star, gbar, stable_gap), with the "// &
            "jumps of 'path --model lj --control gap'"
      else if (given(opts, "--gbar-range") .and. opts%command /= "gaplaw") then
         error = "--gbar-range is only for the gaplaw subcommand"
      else if (opts%command == "gaplaw" .and. .not. given(opts, "--gbar-range")) then
         error = "gaplaw needs --gbar-range LO:HI:N"
      else if (given(opts, "--control") .and. opts%command /= "path" .and. &
         opts%command /= "critical" .and. opts%command /= "map") then
         error = "--control is only for the path, critical and map subcommands"
      else if (opts%command /= "map" .and. control_is(opts, "both")) then
         error = "--control both is only for the map subcommand"
      else if (opts%units == "si" .and. .not. si_given(opts)) then
         error = "--units si needs SI input (--Estar or --E1 --nu1 --E2 --nu2, and "// &
            "--period --amplitude --work-of-adhesion --peak-stress); map has none"
      end if
      if (allocated(error) .or. .not. si_given(opts)) return
      if (given(opts, "--alpha") .or. given(opts, "--mu") .or. given(opts, "--mu-range")) then
         error = "SI options (--E1 ... --peak-stress) cannot be combined with --alpha, "// &
            "--mu or --mu-range (they define alpha and mu): give one or the other"
         return
      end if
      if (given(opts, "--Estar")) then
         do k = 1, 4
            if (given(opts, trim(si_names(k)))) then
               error = "--Estar cannot be combined with "//trim(si_names(k))// &
                  " (give --Estar, or all of --E1 --nu1 --E2 --nu2)"
               return
            end if
         end do
         missing = ""
      else
         missing = missing_of(opts, si_names(1:4))
         if (missing == " --E1 --nu1 --E2 --nu2") missing = " --Estar (or --E1 --nu1 --E2 --nu2)"
      end if
      missing = missing//missing_of(opts, si_names(6:9))
      if (len(missing) > 0) error = "SI input is incomplete: missing"//missing// &
         " (needed: --Estar or --E1 --nu1 --E2 --nu2, and --period --amplitude "// &
         "--work-of-adhesion --peak-stress)"
   end subroutine check_combination

   !> " --x --y" for the names not given.
   pure function missing_of(opts, names) result(missing)
      type(cli_options), intent(in) :: opts
      character(len=*), intent(in) :: names(:)
      character(len=:), allocatable :: missing
      integer :: k
      missing = ""
      do k = 1, size(names)
         if (.not. given(opts, trim(names(k)))) missing = missing//" "//trim(names(k))
      end do
   end function missing_of

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
         case ("lj"); opts%model = model_lj
         case default
            error = "--model: '"//val//"' is not one of westergaard, jkr, dw, md, lj"
         end select
      case ("--alpha"); call parse_real_list(val, "--alpha", opts%alpha, error)
      case ("--mu"); call parse_real_list(val, "--mu", opts%mu, error)
      case ("--a-star"); call parse_real_list(val, "--a-star", opts%a_star, error)
      case ("--c-star"); call parse_real_list(val, "--c-star", opts%c_star, error)
      case ("--n"); call parse_count(val, opts%n_points, error)
      case ("--profile-file")
         if (len(val) == 0) then
            error = "--profile-file: the file name is empty"
         else
            opts%profile_file = val
         end if
      case ("--mu-range"); call parse_mu_range(val, opts%mu, error)
      case ("--alpha-range"); call parse_mu_range(val, opts%alpha, error, "--alpha-range")
      case ("--gbar-range")
         call parse_mu_range(val, opts%gbar, error)
         if (allocated(error)) error = "--gbar-range"//error(len("--mu-range") + 1:)
      case ("--control")
         if (val /= "load" .and. val /= "gap" .and. val /= "both") then
            error = "--control: '"//val//"' is not one of load, gap, both (map)"
         else
            opts%control = val
         end if
      case ("--format")
         if (val /= "table" .and. val /= "csv" .and. val /= "json") then
            error = "--format: '"//val//"' is not one of table, csv, json"
         else
            opts%format = val
         end if
      case ("--units")
         if (val /= "reduced" .and. val /= "si") then
            error = "--units: '"//val//"' is not one of reduced, si"
         else
            opts%units = val
         end if
      case ("--output")
         if (len(val) == 0) then
            error = "--output: the file name is empty"
         else
            opts%output = val
         end if
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

   !> Comma-separated reals, e.g. "0.1,0.2"; each item must be a whole number token.
   subroutine parse_real_list(text, name, values, error)
      character(len=*), intent(in) :: text, name
      real(wp), allocatable, intent(out) :: values(:)
      character(len=:), allocatable, intent(out) :: error
      integer :: start, comma, k, nvals
      nvals = count([(text(k:k) == ",", k=1, len(text))]) + 1
      if (nvals > max_values) then
         error = name//": too many values (at most 100000)"
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

   !> --n N: the number of profile points, an integer in [2, 100000].
   subroutine parse_count(text, n, error)
      character(len=*), intent(in) :: text
      integer, intent(out) :: n
      character(len=:), allocatable, intent(out) :: error
      integer :: ios
      n = 0
      ios = 1
      if (len(text) > 0 .and. len(text) <= 6 .and. verify(text, "0123456789") == 0) &
         read (text, *, iostat=ios) n
      if (ios /= 0 .or. n < 2 .or. n > max_values) &
         error = "--n: '"//text//"' is not an integer in [2, 100000]"
   end subroutine parse_count

   !> LO:HI:N[:log] -> N values of mu from LO to HI, linear or log-spaced.
   subroutine parse_mu_range(text, values, error, option)
      character(len=*), intent(in) :: text
      real(wp), allocatable, intent(out) :: values(:)
      character(len=:), allocatable, intent(out) :: error
      !> The option's name in messages (default --mu-range)
      character(len=*), intent(in), optional :: option
      character(len=:), allocatable :: name
      character(len=*), parameter :: form = "LO:HI:N[:log] with 0 <= LO <= HI "// &
         "(LO > 0 with :log) and N an integer in [1, 100000]"
      character(len=:), allocatable :: part(:)
      real(wp) :: lo, hi
      logical :: logscale
      integer :: n, i, ios

      name = "--mu-range"
      if (present(option)) name = option
      call split(text, ":", part)
      if (size(part) < 3 .or. size(part) > 4) then
         error = name//": '"//text//"' is not LO:HI:N[:log] (expected "//form//")"
         return
      end if
      logscale = size(part) == 4
      if (logscale .and. trim(part(min(4, size(part)))) /= "log") then
         error = name//": '"//trim(part(4))//"' is not 'log' (expected "//form//")"
         return
      end if
      call parse_real(trim(part(1)), name//" LO", lo, error, form)
      if (.not. allocated(error)) call parse_real(trim(part(2)), name//" HI", hi, error, &
         form)
      if (allocated(error)) return
      n = 0
      ios = 1
      if (len_trim(part(3)) > 0 .and. len_trim(part(3)) <= 6 .and. &
         verify(trim(part(3)), "0123456789") == 0) read (part(3), *, iostat=ios) n
      if (ios /= 0 .or. n < 1 .or. n > max_values) then
         error = name//": N = '"//trim(part(3))//"' is not an integer in [1, 100000]"
      else if (.not. (lo >= 0.0_wp .and. hi >= lo)) then
         error = name//": need 0 <= LO <= HI (expected "//form//")"
      else if (logscale .and. lo <= 0.0_wp) then
         error = name//": LO must be > 0 with :log (expected "//form//")"
      end if
      if (allocated(error)) return
      allocate (values(n))
      values(1) = lo
      do i = 2, n
         if (logscale) then
            values(i) = lo*(hi/lo)**(real(i - 1, wp)/real(n - 1, wp))
         else
            values(i) = lo + (hi - lo)*real(i - 1, wp)/real(n - 1, wp)
         end if
      end do
      if (n > 1) values(n) = hi
   end subroutine parse_mu_range

   !> The pieces of text between separators (at most 5).
   pure subroutine split(text, sep, part)
      character(len=*), intent(in) :: text, sep
      character(len=:), allocatable, intent(out) :: part(:)
      integer :: start, k, n, at(6)
      n = 1
      at(1) = 0
      do k = 1, len(text)
         if (text(k:k) /= sep) cycle
         n = n + 1
         if (n > 5) exit
         at(n) = k
      end do
      n = min(n, 5)
      at(n + 1) = len(text) + 1
      allocate (character(len=max(1, len(text))) :: part(n))
      do k = 1, n
         start = at(k) + 1
         part(k) = text(start:at(k + 1) - 1)
      end do
   end subroutine split

   !> One real number: the whole token must be a decimal number, [+-]digits[.digits]
   !> [e[+-]digits] (as C strtod and Python float read it, without inf/nan/hex), and finite.
   subroutine parse_real(text, name, x, error, range)
      character(len=*), intent(in) :: text, name
      real(wp), intent(out) :: x
      character(len=:), allocatable, intent(out) :: error
      !> The valid range, for the message (default: from the option's name)
      character(len=*), intent(in), optional :: range
      character(len=:), allocatable :: expected
      integer :: ios
      x = 0.0_wp
      ios = 1
      if (is_number(text)) read (text, *, iostat=ios) x
      if (present(range)) then
         expected = range
      else
         expected = "a real number in "//valid_range(name)
      end if
      if (ios /= 0) then
         error = name//": '"//text//"' is not a number (expected "//expected//")"
      else if (ieee_is_nan(x) .or. .not. ieee_is_finite(x)) then
         error = name//": '"//text//"' is too large for double precision (expected "// &
            expected//")"
      end if
   end subroutine parse_real

   !> True when text is exactly [+-](d+[.d*] | .d+)[(e|E)[+-]d+].
   pure logical function is_number(text)
      character(len=*), intent(in) :: text
      integer :: i, n, mantissa
      is_number = .false.
      n = len(text)
      i = 1
      if (n == 0) return
      if (scan(text(1:1), "+-") == 1) i = 2
      mantissa = 0
      do while (i <= n)
         if (.not. is_digit(text(i:i))) exit
         mantissa = mantissa + 1
         i = i + 1
      end do
      if (i <= n) then
         if (text(i:i) == ".") then
            i = i + 1
            do while (i <= n)
               if (.not. is_digit(text(i:i))) exit
               mantissa = mantissa + 1
               i = i + 1
            end do
         end if
      end if
      if (mantissa == 0) return
      if (i <= n) then
         if (scan(text(i:i), "eE") /= 1) return
         i = i + 1
         if (i <= n) then
            if (scan(text(i:i), "+-") == 1) i = i + 1
         end if
         if (i > n) return
         do while (i <= n)
            if (.not. is_digit(text(i:i))) return
            i = i + 1
         end do
      end if
      is_number = .true.
   end function is_number

   pure logical function is_digit(c)
      character, intent(in) :: c
      is_digit = c >= "0" .and. c <= "9"
   end function is_digit

   !> A library message that starts with an argument's name ("c_star = 0.9 is outside ...")
   !> with the name spelled as the option that gave it ("--c-star = 0.9 ..."); a message
   !> that starts otherwise is returned unchanged.
   pure function option_message(msg) result(text)
      character(len=*), intent(in) :: msg
      character(len=:), allocatable :: text
      character(len=*), parameter :: options(4) = [character(len=8) :: "--alpha", "--mu", &
         "--a-star", "--c-star"]
      character(len=:), allocatable :: head
      integer :: k, i
      k = scan(msg, " =:")                               ! the end of the leading name
      if (k == 0) k = len(msg) + 1
      head = "--"//msg(1:k - 1)
      do i = 3, len(head)
         if (head(i:i) == "_") head(i:i) = "-"
      end do
      do i = 1, size(options)
         if (head == trim(options(i))) then
            text = head//msg(k:)
            return
         end if
      end do
      do i = 1, size(si_names)
         if (lower(head) == lower(trim(si_names(i)))) then
            text = trim(si_names(i))//msg(k:)
            return
         end if
      end do
      text = msg
   end function option_message

   !> ASCII lower case.
   pure function lower(text) result(low)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: low
      integer :: i
      low = text
      do i = 1, len(text)
         if (text(i:i) >= "A" .and. text(i:i) <= "Z") low(i:i) = achar(iachar(text(i:i)) + 32)
      end do
   end function lower

   !> The valid range of a numeric option, as the library states it.
   pure function valid_range(name) result(range)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: range
      select case (name)
      case ("--alpha"); range = "[1e-12, 1e12]"         ! as wa_params states them
      case ("--mu"); range = "0 or [1e-100, 1e100]"
      case ("--a-star", "--c-star"); range = "[0, 1/2]"
      case ("--E1", "--E2", "--Estar"); range = "(0, inf) Pa"
      case ("--nu1", "--nu2"); range = "(-1, 1/2]"
      case ("--period", "--amplitude"); range = "(0, inf) m"
      case ("--work-of-adhesion"); range = "(0, inf) J/m^2"
      case ("--peak-stress"); range = "[0, inf) Pa"
      case default; range = "(-inf, inf)"
      end select
   end function valid_range

   function model_name(model) result(name)
      integer, intent(in) :: model
      character(len=:), allocatable :: name
      select case (model)
      case (model_westergaard); name = "westergaard"
      case (model_jkr); name = "jkr"
      case (model_dw); name = "dw"
      case (model_lj); name = "lj"
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
      opts%help_topic = ""
      opts%units = "reduced"
      opts%format = "table"
      opts%output = ""
      opts%given = "|"
      opts%e1 = nan; opts%nu1 = nan; opts%e2 = nan; opts%nu2 = nan; opts%estar = nan
      opts%period = nan; opts%amplitude = nan; opts%work = nan; opts%peak = nan
   end subroutine reset

end module wa_cli_options
