!> The CLI's output: a table written to standard output or `--output FILE` (through
!> wa_cli_output). `table` has `#` comment lines and purely numeric rows (reals in
!> ES24.16E3) that Fortran list-directed READ accepts; `csv` has one header row of column
!> names, then the same numbers.
module wa_cli_table
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use wa_kinds, only: wp
   use wavyadhesion, only: params_type, wa_version
   use wa_cli_output, only: sink_type, open_sink, put_line, close_sink, discard_sink
   implicit none
   private

   public :: table_type, open_table, put_text, write_header, write_row, close_table, &
      discard_table, format_real

   !> One output: where it goes, its format and the kind of each column.
   type :: table_type
      type(sink_type) :: sink
      !> "table" or "csv"
      character(len=:), allocatable :: format
      !> Per column: written as an integer (codes, flags) rather than a real
      logical, allocatable :: integer_column(:)
   end type table_type

   !> Columns that hold integer codes or flags (every other column is a real).
   character(len=*), parameter :: integer_names = "|zone_case|stable|event|stage|boundary|"

contains

   !> Open the output (path "" = standard output); see open_sink for ok, no_directory.
   subroutine open_table(tab, format, path, ok, no_directory)
      type(table_type), intent(out) :: tab
      character(len=*), intent(in) :: format, path
      logical, intent(out) :: ok
      logical, intent(out), optional :: no_directory
      tab%format = format
      allocate (tab%integer_column(0))
      call open_sink(tab%sink, path, ok, no_directory)
   end subroutine open_table

   !> One line of text as it is (help, version).
   subroutine put_text(tab, line)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: line
      call put_line(tab%sink, line)
   end subroutine put_text

   !> Comment block (table) or column-name row (csv); `columns` names the columns,
   !> separated by blanks, in the order of write_row's values.
   subroutine write_header(tab, what, model, columns, params, notes)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: what, model, columns
      type(params_type), intent(in), optional :: params
      character(len=*), intent(in), optional :: notes(:)
      character(len=:), allocatable :: names(:)
      integer :: i
      call split_names(columns, names)
      tab%integer_column = [(index(integer_names, "|"//trim(names(i))//"|") > 0, &
         i = 1, size(names))]
      if (tab%format == "csv") then
         call put_line(tab%sink, csv_names(columns))
         return
      end if
      call put_line(tab%sink, "# wavyadhesion "//wa_version//": "//what)
      call put_line(tab%sink, "# model: "//model)
      if (present(params)) then
         call put_line(tab%sink, "# alpha = "//format_real(params%alpha)//"  mu = "// &
            format_real(params%mu))
         call put_line(tab%sink, "# Sigma0 = "//format_real(params%sigma0)//"  Dcod = "// &
            format_real(params%dcod))
      end if
      if (present(notes)) then
         do i = 1, size(notes)
            call put_line(tab%sink, "# "//trim(notes(i)))
         end do
      end if
      call put_line(tab%sink, "# columns: "//columns)
   end subroutine write_header

   !> One row, the values in the order of the header's columns: integer columns as
   !> integers, the others as reals right-aligned in 24 characters (table) or bare (csv).
   subroutine write_row(tab, values)
      type(table_type), intent(inout) :: tab
      real(wp), intent(in) :: values(:)
      character(len=:), allocatable :: line
      character(len=1) :: sep
      integer :: i
      sep = merge(",", " ", tab%format == "csv")
      line = ""
      do i = 1, size(values)
         if (i > 1) line = line//sep
         line = line//field(tab, i, values(i))
      end do
      call put_line(tab%sink, line)
   end subroutine write_row

   !> Column i's text for value x.
   function field(tab, i, x) result(text)
      type(table_type), intent(in) :: tab
      integer, intent(in) :: i
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=12) :: itext
      logical :: is_int
      is_int = .false.
      if (i <= size(tab%integer_column)) is_int = tab%integer_column(i)
      if (is_int) then
         write (itext, '(i0)') nint(x)
         text = trim(itext)
      else
         text = adjustr_field(format_real(x), tab%format)
      end if
   end function field

   !> Flush and close (see close_sink).
   subroutine close_table(tab, ok)
      type(table_type), intent(inout) :: tab
      logical, intent(out) :: ok
      call close_sink(tab%sink, ok)
   end subroutine close_table

   !> Give up: nothing more is written and FILE is left as it was (see discard_sink).
   subroutine discard_table(tab)
      type(table_type), intent(inout) :: tab
      call discard_sink(tab%sink)
   end subroutine discard_table

   !> ES24.16E3, or Infinity / -Infinity / NaN spelled so strtod and float() read them.
   function format_real(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=24) :: buf
      if (ieee_is_nan(x)) then
         text = "NaN"
      else if (.not. ieee_is_finite(x)) then
         text = merge("Infinity ", "-Infinity", x > 0.0_wp)
         text = trim(text)
      else
         write (buf, '(es24.16e3)') x
         text = trim(adjustl(buf))
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
      character(len=:), allocatable, intent(out) :: names(:)
      integer :: i, k, n, start
      n = 0
      do i = 1, len(columns)
         if (columns(i:i) /= " " .and. (i == 1 .or. columns(max(i - 1, 1):max(i - 1, 1)) == " ")) &
            n = n + 1
      end do
      allocate (character(len=max(1, len(columns))) :: names(n))
      k = 0
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
         k = k + 1
         names(k) = columns(start:i - 1)
      end do
   end subroutine split_names

   function csv_names(columns) result(names)
      character(len=*), intent(in) :: columns
      character(len=:), allocatable :: names
      integer :: i
      names = trim(adjustl(columns))
      do i = 1, len(names)
         if (names(i:i) == " ") names(i:i) = ","
      end do
   end function csv_names

end module wa_cli_table
