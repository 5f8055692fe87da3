!> The CLI's help text (`wavyadhesion --help`).
module wa_cli_help
   use wa_cli_table, only: table_type, put_text
   implicit none
   private

   public :: print_help

contains

   subroutine print_help(tab)
      type(table_type), intent(inout) :: tab
      integer :: i
      character(len=100), parameter :: text(52) = [character(len=100) :: &
         "Usage: wavyadhesion [SUBCOMMAND] [OPTIONS]", &
         "", &
         "Adhesive contact of a wavy elastic surface against a flat (Westergaard, JKR,", &
         "double-Westergaard, Maugis-Dugdale). Dimensionless loads P* = mean traction/p*,", &
         "p* = pi E* Delta/L; widths a* = a/L, c* = c/L.", &
         "", &
         "Subcommands:", &
         "  branch    the equilibrium curve P*(a*), c*(a*) with folds and case switches", &
         "            (default; alpha=0.3, mu=1, dw)", &
         "  point     every equilibrium at given a*: --a-star X[,X...]", &
         "  profile   traction and gap of one state over x* in [-1/2, 1/2]: --a-star X", &
         "            [--c-star C] (default: the principal state) [--n N] (default 201)", &
         "  path      loading and unloading under load control: jumps, full contact,", &
         "            pull-off; --control gap: approach and retraction under mean-gap", &
         "            control (jumps, contact made/lost, energy lost per cycle W*)", &
         "  gaplaw    P* on approach and retraction and dP*/dgbar* on a uniform grid of", &
         "            mean gaps: --gbar-range LO:HI:N", &
         "  critical  P_fc and P_pf over --alpha A[,A...] and --mu U[,U...] or", &
         "            --mu-range LO:HI:N[:log] (--control gap: those of mean-gap control)", &
         "  map       adhesion map (dw, md): boundaries between mechanisms as rows", &
         "            'boundary alpha mu' (--alpha-range, default 0.01:10:200:log;", &
         "            --mu-range, default 1e-3:1e3:60:log); --control gap|both: the", &
         "            boundaries under mean-gap control (codes 3xx approach, 4xx", &
         "            retraction) instead of / with the load-control ones", &
         "", &
         "Options:", &
         "  --model M          westergaard | jkr | dw | md (default dw)", &
         "  --alpha A          Johnson's parameter, in [1e-12, 1e12] (default 0.3)", &
         "  --mu U             transition parameter, 0 or in [1e-100, 1e100] (default 1)", &
         "  --mu-range LO:HI:N[:log]", &
         "                     N values of mu from LO to HI (critical, map; not with --mu)", &
         "  --alpha-range LO:HI:N[:log]", &
         "                     N values of alpha (map only; not with --alpha)", &
         "  --a-star X[,X...]  contact half-widths over the period, in [0, 1/2] (point;", &
         "                     profile: one value)", &
         "  --c-star C         profile: c* of the state (within 1e-6; md at a* = 0: the", &
         "                     Dugdale zone half-width of a state without contact)", &
         "  --n N              profile: number of points, in [2, 100000] (default 201)", &
         "  --control C        load (default) | gap (path, critical, map) | both (map)", &
         "  --gbar-range LO:HI:N  mean gaps gbar* >= 0 (gaplaw)", &
         "  --format F         table (default, # comments + numeric rows) | csv", &
         "  --output FILE      write the table to FILE instead of standard output; FILE is", &
         "                     replaced only once the whole table is written", &
         "  --help, --version", &
         "SI input instead of --alpha/--mu/--mu-range (the whole set, not mixed):", &
         "  --Estar, or all of --E1 --nu1 --E2 --nu2 [Pa], --period --amplitude [m],", &
         "  --work-of-adhesion [J/m^2], --peak-stress [Pa]", &
         "", &
         "Numbers are decimal (0.3, -1, 2.5e-3); each option may be given once.", &
         "Exit status: 0 ok; 2 usage error; 1 numerical failure or write error. No table", &
         "is written on failure, except by critical, which writes every row (NaN where a", &
         "row failed, named on standard error) and then exits with 1."]
      do i = 1, size(text)
         call put_text(tab, trim(text(i)))
      end do
   end subroutine print_help

end module wa_cli_help
