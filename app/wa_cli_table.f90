!> The CLI's output: a table written to standard output or `--output FILE` (through
!> wa_cli_output), in one of three formats:
!> - `table`: `#` comment lines, then purely numeric rows (reals in ES24.16E3) that
!>   Fortran list-directed READ accepts. The first line is `# ` and the column names, so
!>   numpy.genfromtxt(names=True) names the columns; the last comment line repeats them
!>   after `# columns:`.
!> - `csv`: one row of column names, then the same numbers.
!> - `json`: one document with the metadata (version, model, parameters, SI scales,
!>   results such as P_fc or W*, the header notes) and the columns as arrays by name;
!>   written when the table is closed (wa_cli_json for the non-finite values).
!> With SI input and `--units si`, every column that has a unit is followed, after the
!> dimensionless columns, by its SI column (wa_cli_units).
module wa_cli_table
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use wa_kinds, only: wp
   use wa_text, only: real_text, int_text
   use wavyadhesion, only: params_type, wa_version
   use wa_cli_output, only: sink_type, open_sink, put_line, close_sink, discard_sink
   use wa_cli_units, only: si_scales_type, si_column
   use wa_cli_json, only: json_string, json_real, json_int, json_real_list, nonfinite_note
   implicit none
   private

   public :: table_type, open_table, set_units, put_text, add_value, write_header, &
      write_row, close_table, discard_table, format_real

   integer, parameter :: name_len = 40, note_len = 400

   !> One output: where it goes, its format, its columns, and (json) what it holds.
   type :: table_type
      type(sink_type) :: sink
      !> "table", "csv" or "json"; the subcommand
      character(len=:), allocatable :: format, command
      type(si_scales_type) :: scales
      !> --units si: SI columns after the dimensionless ones
      logical :: si_columns = .false.
      !> Every column (dimensionless, then SI) and which are integer codes or flags
      character(len=name_len), allocatable :: names(:), units(:)
      logical, allocatable :: integer_column(:)
      !> Per SI column: the dimensionless column it comes from, and the factor
      integer, allocatable :: si_of(:)
      real(wp), allocatable :: si_factor(:)
      !> The header, kept for json
      character(len=:), allocatable :: what, model
      logical :: has_params = .false.
      type(params_type) :: params
      character(len=note_len), allocatable :: notes(:)
      !> Named results (P_fc, W_star, ...): scalars or lists, in `value_data`
      character(len=name_len), allocatable :: value_names(:)
      integer, allocatable :: value_start(:), value_count(:)
      logical, allocatable :: value_int(:), value_list(:)
      real(wp), allocatable :: value_data(:)
      !> json: the rows, one per column of `rows` (capacity doubles)
      real(wp), allocatable :: rows(:, :)
      integer :: n_rows = 0
      logical :: header_written = .false.
   end type table_type

   !> Columns that hold integer codes or flags (every other column is a real).
   character(len=*), parameter :: integer_names = "|zone_case|stable|event|stage|boundary|stable_gap|extremum|"

contains

   !> Open the output (path "" = standard output); see open_sink for ok, no_directory.
   subroutine open_table(tab, format, path, ok, no_directory)
      type(table_type), intent(out) :: tab
      character(len=*), intent(in) :: format, path
      logical, intent(out) :: ok
      logical, intent(out), optional :: no_directory
      tab%format = format
      tab%command = ""
      allocate (tab%names(0), tab%units(0), tab%integer_column(0), tab%si_of(0), &
         tab%si_factor(0), tab%notes(0), tab%value_names(0), tab%value_start(0), &
         tab%value_count(0), tab%value_int(0), tab%value_list(0), tab%value_data(0))
      call open_sink(tab%sink, path, ok, no_directory)
   end subroutine open_table

   !> The subcommand (for json), the SI scales (when SI input was given) and whether SI
   !> columns are added (--units si).
   subroutine set_units(tab, command, scales, si_columns)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: command
      type(si_scales_type), intent(in) :: scales
      logical, intent(in) :: si_columns
      tab%command = command
      tab%scales = scales
      tab%si_columns = si_columns .and. scales%given
   end subroutine set_units

   !> One line of text as it is (help, version).
   subroutine put_text(tab, line)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: line
      call put_line(tab%sink, line)
   end subroutine put_text

   !> A named result (json "values"; with --units si also its SI value in the header):
   !> one value, or a list (`x` of any size with list = .true.); `integers`: codes.
   subroutine add_value(tab, name, x, list, integers)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: x(:)
      logical, intent(in), optional :: list, integers
      logical :: is_list, is_int
      is_list = .false.
      is_int = .false.
      if (present(list)) is_list = list
      if (present(integers)) is_int = integers
      tab%value_names = [character(len=name_len) :: tab%value_names, name]
      tab%value_start = [tab%value_start, size(tab%value_data) + 1]
      tab%value_count = [tab%value_count, size(x)]
      tab%value_int = [tab%value_int, is_int]
      tab%value_list = [tab%value_list, is_list]
      tab%value_data = [tab%value_data, x]
   end subroutine add_value

   !> The header: comment block (table), column-name row (csv), or kept for the
   !> document (json). `columns` names the columns, separated by blanks, in the order of
   !> write_row's values.
   subroutine write_header(tab, what, model, columns, params, notes)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: what, model, columns
      type(params_type), intent(in), optional :: params
      character(len=*), intent(in), optional :: notes(:)
      character(len=:), allocatable :: unit, si_name
      real(wp) :: factor
      integer :: i, n_base

      call split_names(columns, tab%names)
      n_base = size(tab%names)
      tab%units = [(repeat(" ", name_len), i = 1, n_base)]
      if (tab%si_columns) then
         do i = 1, n_base
            call si_column(trim(tab%names(i)), tab%scales, si_name, unit, factor)
            if (len(si_name) == 0) cycle
            tab%names = [character(len=name_len) :: tab%names, si_name]
            tab%units = [character(len=name_len) :: tab%units, unit]
            tab%si_of = [tab%si_of, i]
            tab%si_factor = [tab%si_factor, factor]
         end do
      end if
      tab%integer_column = [(index(integer_names, "|"//trim(tab%names(i))//"|") > 0, &
         i = 1, size(tab%names))]
      tab%what = what
      tab%model = model
      tab%has_params = present(params)
      if (present(params)) tab%params = params
      if (present(notes)) tab%notes = [character(len=note_len) :: notes]
      tab%header_written = .true.
      select case (tab%format)
      case ("csv"); call put_line(tab%sink, joined(tab%names, ","))
      case ("table"); call write_comments(tab)
      case default
         allocate (tab%rows(size(tab%names), 64))
      end select
   end subroutine write_header

   !> The table format's comment block.
   subroutine write_comments(tab)
      type(table_type), intent(inout) :: tab
      character(len=:), allocatable :: line
      integer :: i, k
      call put_line(tab%sink, "# "//joined(tab%names, " "))
      call put_line(tab%sink, "# wavyadhesion "//wa_version//": "//tab%what)
      call put_line(tab%sink, "# model: "//tab%model)
      if (tab%has_params) then
         call put_line(tab%sink, "# alpha = "//format_real(tab%params%alpha)//"  mu = "// &
            format_real(tab%params%mu))
         call put_line(tab%sink, "# Sigma0 = "//format_real(tab%params%sigma0)//"  Dcod = "// &
            format_real(tab%params%dcod))
      end if
      if (tab%scales%given) then
         associate (s => tab%scales)
            call put_line(tab%sink, "# SI scales: E* = "//format_real(s%estar)//" Pa, p* = "// &
               "pi E* Delta/L = "//format_real(s%pressure)//" Pa, p* L = "// &
               format_real(s%force)//" N/m")
            call put_line(tab%sink, "# SI scales: L = "//format_real(s%length)//" m, Delta = "// &
               format_real(s%delta)//" m, p* Delta = "//format_real(s%energy)//" J/m^2")
         end associate
      end if
      do i = 1, size(tab%notes)
         call put_line(tab%sink, "# "//trim(tab%notes(i)))
      end do
      if (tab%si_columns) then
         line = "# SI columns (--units si):"
         do k = 1, size(tab%si_of)
            i = size(tab%names) - size(tab%si_of) + k
            line = line//" "//trim(tab%names(i))//" ["//trim(tab%units(i))//"]"
         end do
         call put_line(tab%sink, line)
         do k = 1, size(tab%value_names)
            call si_value_line(tab, k)
         end do
      end if
      call put_line(tab%sink, "# columns: "//joined(tab%names, " "))
   end subroutine write_comments

   !> "# SI: P_fc_Pa = ..." for named result k when it has a unit.
   subroutine si_value_line(tab, k)
      type(table_type), intent(inout) :: tab
      integer, intent(in) :: k
      character(len=:), allocatable :: si_name, unit, line
      real(wp) :: factor
      integer :: j
      call si_column(trim(tab%value_names(k)), tab%scales, si_name, unit, factor)
      if (len(si_name) == 0 .or. tab%value_count(k) == 0) return
      line = "# SI: "//si_name//" ="
      do j = tab%value_start(k), tab%value_start(k) + tab%value_count(k) - 1
         line = line//" "//format_real(factor*tab%value_data(j))
      end do
      call put_line(tab%sink, line//" "//unit)
   end subroutine si_value_line

   !> One row, the values in the order of the header's columns (the SI columns are
   !> added here): integer columns as integers, the others as reals right-aligned in 24
   !> characters (table) or bare (csv); json keeps the row until the table is closed.
   subroutine write_row(tab, values)
      type(table_type), intent(inout) :: tab
      real(wp), intent(in) :: values(:)
      real(wp), allocatable :: all(:), grown(:, :)
      character(len=:), allocatable :: line
      character(len=1) :: sep
      integer :: i
      all = [values, (tab%si_factor(i)*values(tab%si_of(i)), i = 1, size(tab%si_of))]
      if (tab%format == "json") then
         if (tab%n_rows == size(tab%rows, 2)) then
            allocate (grown(size(tab%rows, 1), 2*size(tab%rows, 2)))
            grown(:, 1:tab%n_rows) = tab%rows(:, 1:tab%n_rows)
            call move_alloc(grown, tab%rows)
         end if
         tab%n_rows = tab%n_rows + 1
         tab%rows(:, tab%n_rows) = all
         return
      end if
      sep = merge(",", " ", tab%format == "csv")
      line = ""
      do i = 1, size(all)
         if (i > 1) line = line//sep
         line = line//field(tab, i, all(i))
      end do
      call put_line(tab%sink, line)
   end subroutine write_row

   !> Column i's text for value x.
   function field(tab, i, x) result(text)
      type(table_type), intent(in) :: tab
      integer, intent(in) :: i
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      logical :: is_int
      is_int = .false.
      if (i <= size(tab%integer_column)) is_int = tab%integer_column(i)
      if (is_int) then
         text = int_text(nint(x))
      else
         text = adjustr_field(format_real(x), tab%format)
      end if
   end function field

   !> Write the json document (json format), flush and close (see close_sink).
   subroutine close_table(tab, ok)
      type(table_type), intent(inout) :: tab
      logical, intent(out) :: ok
      if (tab%format == "json" .and. tab%header_written) call write_json(tab)
      call close_sink(tab%sink, ok)
   end subroutine close_table

   !> The json document: metadata first, then "data" with one array per column.
   subroutine write_json(tab)
      type(table_type), intent(inout) :: tab
      character(len=:), allocatable :: item
      integer, allocatable :: used(:)
      integer :: i, k, j
      call put_line(tab%sink, "{")
      call put_line(tab%sink, '  "program": "wavyadhesion",')
      call put_line(tab%sink, '  "version": '//json_string(wa_version)//",")
      call put_line(tab%sink, '  "subcommand": '//json_string(tab%command)//",")
      call put_line(tab%sink, '  "title": '//json_string(tab%what)//",")
      call put_line(tab%sink, '  "model": '//json_string(tab%model)//",")
      if (tab%has_params) call put_line(tab%sink, '  "parameters": {"alpha": '// &
         json_real(tab%params%alpha)//', "mu": '//json_real(tab%params%mu)// &
         ', "Sigma0": '//json_real(tab%params%sigma0)//', "Dcod": '// &
         json_real(tab%params%dcod)//"},")
      if (tab%scales%given) then
         associate (s => tab%scales)
            call put_line(tab%sink, '  "scales": {"Estar_Pa": '//json_real(s%estar)// &
               ', "p_star_Pa": '//json_real(s%pressure)//', "p_star_L_N_per_m": '// &
               json_real(s%force)//', "L_m": '//json_real(s%length)//', "Delta_m": '// &
               json_real(s%delta)//', "p_star_Delta_J_per_m2": '//json_real(s%energy)//"},")
         end associate
      end if
      call put_line(tab%sink, '  "values": {')
      do k = 1, size(tab%value_names)
         associate (x => tab%value_data(tab%value_start(k):tab%value_start(k) + &
            tab%value_count(k) - 1))
            if (tab%value_list(k)) then
               item = json_real_list(x, tab%value_int(k))
            else if (tab%value_int(k)) then
               item = json_int(nint(x(1)))
            else
               item = json_real(x(1))
            end if
         end associate
         call put_line(tab%sink, "    "//json_string(trim(tab%value_names(k)))//": "//item// &
            trim(merge(",", " ", k < size(tab%value_names))))
      end do
      call put_line(tab%sink, "  },")
      call put_line(tab%sink, '  "notes": [')
      used = pack([(i, i = 1, size(tab%notes))], len_trim(tab%notes) > 0)
      do k = 1, size(used)
         call put_line(tab%sink, "    "//json_string(trim(tab%notes(used(k))))// &
            trim(merge(",", " ", k < size(used))))
      end do
      call put_line(tab%sink, "  ],")
      call put_line(tab%sink, '  "nonfinite": '//json_string(nonfinite_note)//",")
      item = ""
      do i = 1, size(tab%names)
         item = item//merge(", ", "  ", i > 1)//json_string(trim(tab%names(i)))
      end do
      call put_line(tab%sink, '  "columns": ['//item(3:)//"],")
      item = ""
      do i = 1, size(tab%names)
         if (len_trim(tab%units(i)) > 0) item = item//", "//json_string(trim(tab%names(i)))// &
            ": "//json_string(trim(tab%units(i)))
      end do
      if (len(item) > 0) call put_line(tab%sink, '  "units": {'//item(3:)//"},")
      call put_line(tab%sink, '  "n_rows": '//json_int(tab%n_rows)//",")
      call put_line(tab%sink, '  "data": {')
      do j = 1, size(tab%names)
         call put_line(tab%sink, "    "//json_string(trim(tab%names(j)))//": "// &
            json_real_list(tab%rows(j, 1:tab%n_rows), tab%integer_column(j))// &
            trim(merge(",", " ", j < size(tab%names))))
      end do
      call put_line(tab%sink, "  }")
      call put_line(tab%sink, "}")
   end subroutine write_json

   !> Give up: nothing more is written and FILE is left as it was (see discard_sink).
   subroutine discard_table(tab)
      type(table_type), intent(inout) :: tab
      call discard_sink(tab%sink)
   end subroutine discard_table

   !> ES24.16E3, or Infinity / -Infinity / NaN spelled so strtod and float() read them.
   function format_real(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      if (ieee_is_nan(x)) then
         text = "NaN"
      else if (.not. ieee_is_finite(x)) then
         text = merge("Infinity ", "-Infinity", x > 0.0_wp)
         text = trim(text)
      else
         text = real_text(x)
      end if
   end function format_real

   function adjustr_field(text, format) result(field)
      character(len=*), intent(in) :: text, format
      character(len=:), allocatable :: field
      if (format == "csv" .or. len(text) >= 24) then
         field = text
      else
         field = repeat(" ", 24 - len(text))//text
      end if
   end function adjustr_field

   !> The blank-separated names of `columns`.
   pure subroutine split_names(columns, names)
      character(len=*), intent(in) :: columns
      character(len=name_len), allocatable, intent(inout) :: names(:)
      integer :: i, start
      if (allocated(names)) deallocate (names)
      allocate (names(0))
      i = 1
      do while (i <= len(columns))
         if (columns(i:i) == " ") then
            i = i + 1
            cycle
         end if
         start = i
         do while (i <= len(columns))
            if (columns(i:i) == " ") exit
            i = i + 1
         end do
         names = [character(len=name_len) :: names, columns(start:i - 1)]
      end do
   end subroutine split_names

   !> The names joined by `sep`.
   pure function joined(names, sep) result(text)
      character(len=*), intent(in) :: names(:), sep
      character(len=:), allocatable :: text
      integer :: i
      text = ""
      do i = 1, size(names)
         if (i > 1) text = text//sep
         text = text//trim(names(i))
      end do
   end function joined

end module wa_cli_table
