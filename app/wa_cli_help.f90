!> The CLI's help: `wavyadhesion --help` (or `help`) prints the global text,
!> `wavyadhesion help SUBCOMMAND` and `wavyadhesion SUBCOMMAND --help` that subcommand's
!> options, columns and examples.
module wa_cli_help
   use wa_cli_table, only: table_type, put_text
   implicit none
   private

   public :: print_help

contains

   !> The help on `topic` (a subcommand, or "" for the global help).
   subroutine print_help(tab, topic)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: topic
      select case (topic)
      case ("branch"); call put_lines(tab, help_branch())
      case ("point"); call put_lines(tab, help_point())
      case ("profile"); call put_lines(tab, help_profile())
      case ("path"); call put_lines(tab, help_path())
      case ("gaplaw"); call put_lines(tab, help_gaplaw())
      case ("critical"); call put_lines(tab, help_critical())
      case ("map"); call put_lines(tab, help_map())
      case default; call put_lines(tab, help_global())
      end select
   end subroutine print_help

   subroutine put_lines(tab, text)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: text(:)
      integer :: i
      do i = 1, size(text)
         call put_text(tab, trim(text(i)))
      end do
   end subroutine put_lines

   pure function help_global() result(text)
      character(len=100) :: text(70)
      character(len=100), parameter :: lines(70) = [character(len=100) :: &
         "Usage: wavyadhesion [SUBCOMMAND] [OPTIONS]", &
         "       wavyadhesion help [SUBCOMMAND]      (or SUBCOMMAND --help): one subcommand's", &
         "                                            options, columns and examples", &
         "", &
         "Adhesive contact of a wavy elastic surface against a flat (Westergaard, JKR,", &
         "double-Westergaard, Maugis-Dugdale; smooth Lennard-Jones, --model lj).", &
         "Dimensionless loads P* = mean traction/p*,", &
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
         "  --model M          westergaard | jkr | dw | md | lj (default dw); lj: the smooth", &
         "                     Lennard-Jones 3-9 law with the same work of adhesion and range", &
         "                     eps = dgamma/sigma0 = 2 Dcod Delta (mu keeps its meaning; its", &
         "                     peak tension is 16/(9 sqrt 3) sigma0); branch, path, critical,", &
         "                     profile; results carry N vs N/2 error estimates (_err)", &
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
         "  --n N              profile: number of points, in [2, 100000] (default 201);", &
         "                     --model lj: grid points per period, even, >= 8 (default:", &
         "                     automatic, 12 points on the interaction zone)", &
         "  --profile-file F   --model lj: the surface as samples of one period, one height", &
         "                     over Delta per line at x* = j/M, j = 0..M-1 (# comments);", &
         "                     default the sinusoid 1 - cos(2 pi x*)", &
         "  --control C        load (default) | gap (path, critical, map) | both (map)", &
         "  --gbar-range LO:HI:N  mean gaps gbar* >= 0 (gaplaw)", &
         "  --format F         table (default: # comments, the first naming the columns,", &
         "                     then numeric rows) | csv | json (one document: metadata and", &
         "                     the columns as arrays; NaN, Infinity as strings)", &
         "  --units U          reduced (default) | si: with SI input, add SI columns", &
         "                     (a_m [m], P_Pa [Pa], gbar_m [m], ...) after the others", &
         "  --output FILE      write the table to FILE instead of standard output; FILE is", &
         "                     replaced only once the whole table is written", &
         "  --help, --version", &
         "SI input instead of --alpha/--mu/--mu-range (the whole set, not mixed):", &
         "  --Estar, or all of --E1 --nu1 --E2 --nu2 [Pa], --period --amplitude [m],", &
         "  --work-of-adhesion [J/m^2], --peak-stress [Pa]", &
         "  The header then gives the scales p*, p* L, L, Delta and p* Delta.", &
         "", &
         "Numbers are decimal (0.3, -1, 2.5e-3); each option may be given once.", &
         "Exit status: 0 ok; 2 usage error; 1 numerical failure or write error. No table", &
         "is written on failure, except by critical, which writes every row (NaN where a", &
         "row failed, named on standard error) and then exits with 1. On a terminal, runs", &
         "longer than about a second show their progress on standard error."]
      text = lines
   end function help_global

   pure function help_branch() result(text)
      character(len=100) :: text(25)
      character(len=100), parameter :: lines(25) = [character(len=100) :: &
         "Usage: wavyadhesion branch [--model M] [--alpha A] [--mu U]", &
         "", &
         "The equilibrium curve by pseudo-arclength continuation from a* -> 0 to a* = 1/2,", &
         "with its folds, zone-case switches and a*-turns (the default subcommand).", &
         "", &
         "Columns:", &
         "  a_star c_star P_star  contact and zone half-widths over the period, load P*", &
         "  b_star                a* + 0.4 (c* - a*) (a point inside the adhesive zone)", &
         "  zone_case             0 no contact (md), 1 a*<c*<1/2, 2 c*=1/2, 3 full contact", &
         "  stable                1 = stable under load control", &
         "  event                 0 none, 1 fold, 2 zone-case switch, 8 branch end,", &
         "                        9 a*-turn (the codes are in the header)", &
         "  gbar                  mean gap over Delta", &
         "  --units si adds a_m c_m b_m [m], P_Pa [Pa], gbar_m [m].", &
         "", &
         "Common options: --model M, --alpha A, --mu U (or the SI input), --format", &
         "table|csv|json, --units reduced|si, --output FILE (wavyadhesion --help).", &
         "", &
         "Examples:", &
         "  wavyadhesion branch --model dw --alpha 0.3 --mu 5", &
         "  wavyadhesion branch --model md --alpha 0.6 --mu 1 --format csv", &
         "--model lj: columns a_star b_star P_star stable stable_gap event extremum gbar", &
         "  h_min h_max (b*: half the measure of {h <= 3^(1/6) eps}, the peak tension);", &
         "  the header gives P_fc, P_pf and W* on the curve with their error estimates.", &
         "  wavyadhesion branch --model lj --alpha 0.3 --mu 3 --n 256"]
      text = lines
   end function help_branch

   pure function help_point() result(text)
      character(len=100) :: text(17)
      character(len=100), parameter :: lines(17) = [character(len=100) :: &
         "Usage: wavyadhesion point --a-star X[,X...] [--model M] [--alpha A] [--mu U]", &
         "", &
         "Every equilibrium state at each given a* (MD can have several; Westergaard and", &
         "JKR one, with c* = a*). --a-star values are in [0, 1/2], at most 100000.", &
         "", &
         "Columns:", &
         "  a_star c_star P_star  contact and zone half-widths over the period, load P*", &
         "  zone_case             1 a*<c*<1/2, 2 c*=1/2, 3 full contact", &
         "  gbar                  mean gap over Delta (NaN where not defined)", &
         "  --units si adds a_m c_m [m], P_Pa [Pa], gbar_m [m].", &
         "", &
         "Common options: --model M, --alpha A, --mu U (or the SI input), --format", &
         "table|csv|json, --units reduced|si, --output FILE (wavyadhesion --help).", &
         "", &
         "Examples:", &
         "  wavyadhesion point --model md --alpha 0.3 --mu 1 --a-star 0.1,0.2,0.3", &
         "  wavyadhesion point --a-star 0.2 --format json"]
      text = lines
   end function help_point

   pure function help_profile() result(text)
      character(len=100) :: text(23)
      character(len=100), parameter :: lines(23) = [character(len=100) :: &
         "Usage: wavyadhesion profile --a-star X [--c-star C] [--n N] [--model M] ...", &
         "", &
         "Traction and gap of one state at N points x* from -1/2 to 1/2 (crest at x* = 0).", &
         "The state: the principal one at a* (default) or the one whose c* is within 1e-6", &
         "of --c-star (md at a* = 0: the state without contact with Dugdale zone c*).", &
         "--n N: number of points, in [2, 100000] (default 201).", &
         "", &
         "Columns:", &
         "  x_star     position over the period", &
         "  traction   p/p* (positive = compressive)", &
         "  gap        h/Delta (0 on the contact)", &
         "  --units si adds x_m [m], traction_Pa [Pa], gap_m [m].", &
         "The header names the state (a*, c*, P*, zone case, gbar); json: ""values"".", &
         "", &
         "Common options: --model M, --alpha A, --mu U (or the SI input), --format", &
         "table|csv|json, --units reduced|si, --output FILE (wavyadhesion --help).", &
         "", &
         "Examples:", &
         "  wavyadhesion profile --model md --alpha 0.3 --mu 1 --a-star 0.2", &
         "  wavyadhesion profile --model md --a-star 0 --c-star 0.05 --n 11", &
         "--model lj: the traced (load-stable) state with a* nearest --a-star, at the N", &
         "  grid nodes (--n: the grid).", &
         "  wavyadhesion profile --model lj --alpha 0.3 --mu 1 --a-star 0.2 --n 64"]
      text = lines
   end function help_profile

   pure function help_path() result(text)
      character(len=100) :: text(28)
      character(len=100), parameter :: lines(28) = [character(len=100) :: &
         "Usage: wavyadhesion path [--control load|gap] [--model M] [--alpha A] [--mu U]", &
         "", &
         "--control load (default): loading from P* = 0 (stage 1) and unloading from full", &
         "contact (stage 2) under load control. The header gives P_fc, P_pf, the energy", &
         "released by each jump (p* Delta per period) and the P-a loop area.", &
         "--control gap: approach from far apart (stage 1) and retraction (stage 2) under", &
         "mean-gap control; the header gives the energy lost per cycle W* and W*/(pi", &
         "alpha^2/2).", &
         "", &
         "Columns:", &
         "  stage event               1/2; event codes in the header (3 jump start, 4 jump", &
         "                            end, 5/6 full contact reached/left, 7 pull-off; gap", &
         "                            control: 10 touch, 11 contact made, 12 contact lost,", &
         "                            13 interaction lost)", &
         "  a_star c_star P_star      the state at the event", &
         "  gbar                      (--control gap) mean gap over Delta", &
         "  --units si adds a_m c_m [m], P_Pa [Pa] (gbar_m [m]); the header P_fc_Pa,", &
         "  P_pf_Pa, jump_energies_J_per_m2 or W_J_per_m2.", &
         "", &
         "Common options: --model M, --alpha A, --mu U (or the SI input), --format", &
         "table|csv|json, --units reduced|si, --output FILE (wavyadhesion --help).", &
         "", &
         "Examples:", &
         "  wavyadhesion path --alpha 0.3 --mu 5 --format csv", &
         "  wavyadhesion path --control gap --model md --alpha 0.3 --mu 1", &
         "--model lj: columns stage event a_star P_star gbar; the header gives P_fc, P_pf,", &
         "  P_snap (load control) or W* (gap control) with their error estimates _err.", &
         "  wavyadhesion path --model lj --control gap --alpha 0.3 --mu 3"]
      text = lines
   end function help_path

   pure function help_gaplaw() result(text)
      character(len=100) :: text(18)
      character(len=100), parameter :: lines(18) = [character(len=100) :: &
         "Usage: wavyadhesion gaplaw --gbar-range LO:HI:N [--model M] [--alpha A] [--mu U]", &
         "", &
         "P* on the approach and retraction curves of mean-gap control and their slopes", &
         "dP*/dgbar* at N mean gaps gbar* from LO to HI (LO >= 0). Inside a hysteresis loop", &
         "the two differ: the history picks the column (doc/user-guide.md).", &
         "", &
         "Columns:", &
         "  gbar                          mean gap over Delta", &
         "  P_approach P_retract          P* after approaching / after retracting", &
         "  dPdg_approach dPdg_retract    slopes (-Infinity at full contact)", &
         "  --units si adds gbar_m [m], P_approach_Pa P_retract_Pa [Pa],", &
         "  dPdg_approach_Pa_per_m dPdg_retract_Pa_per_m [Pa/m].", &
         "", &
         "Common options: --model M, --alpha A, --mu U (or the SI input), --format", &
         "table|csv|json, --units reduced|si, --output FILE (wavyadhesion --help).", &
         "", &
         "Example:", &
         "  wavyadhesion gaplaw --model md --alpha 0.3 --mu 1 --gbar-range 0:1.5:31"]
      text = lines
   end function help_gaplaw

   pure function help_critical() result(text)
      character(len=100) :: text(28)
      character(len=100), parameter :: lines(28) = [character(len=100) :: &
         "Usage: wavyadhesion critical [--alpha A[,A...]] [--mu U[,U...] | --mu-range", &
         "       LO:HI:N[:log]] [--control load|gap] [--model M]", &
         "", &
         "Critical values over every (alpha, mu) (SI input: its one alpha, mu). A row that", &
         "fails is written with NaN values and named on standard error; the exit status", &
         "is then 1.", &
         "--control load (default): the header (table, json) locates each change of", &
         "mechanism in mu (to 1e-10).", &
         "", &
         "Columns (load control):", &
         "  alpha mu      the parameters", &
         "  P_fc          load at which full contact is first reached (loading from 0)", &
         "  P_pf          pull-off load on unloading from full contact (-Infinity: never)", &
         "Columns (--control gap): alpha mu g_touch P_jump_in a_jump_in g_contact P_min", &
         "  g_P_min a_P_min g_contact_lost P_contact_lost g_interaction_lost (meanings in", &
         "  the header)", &
         "  --units si adds the P_* columns in Pa, the g_* and a_* columns in m.", &
         "", &
         "Common options: --model M, --alpha A, --mu U (or the SI input), --format", &
         "table|csv|json, --units reduced|si, --output FILE (wavyadhesion --help).", &
         "", &
         "Examples:", &
         "  wavyadhesion critical --model dw --alpha 0.3,0.6,1 --mu-range 0.01:10:200:log", &
         "  wavyadhesion critical --control gap --model md --alpha 0.3 --mu 1,5", &
         "--model lj: columns alpha mu P_fc P_pf P_fc_err P_pf_err P_fc_peak P_fc_peak_err", &
         "  (--control gap: alpha mu W_star W_fraction W_star_err); _err = |value at N -", &
         "  value at N/2|; P_fc_peak: load at which b* first reaches 1/2 (DW's, MD's P_fc).", &
         "  wavyadhesion critical --model lj --alpha 0.3 --mu 3"]
      text = lines
   end function help_critical

   pure function help_map() result(text)
      character(len=100) :: text(20)
      character(len=100), parameter :: lines(20) = [character(len=100) :: &
         "Usage: wavyadhesion map --model dw|md [--alpha-range LO:HI:N[:log] | --alpha", &
         "       A[,A...]] [--mu-range LO:HI:N[:log]] [--control load|gap|both]", &
         "", &
         "The adhesion map: the curves mu_b(alpha) where a mechanism changes, each point", &
         "located to 2e-9 relative in mu. Defaults: --alpha-range 0.01:10:200:log,", &
         "--mu-range 1e-3:1e3:60:log (the scan; the curves are located between). No SI", &
         "input. --control gap|both: the boundaries of mean-gap control instead of / with", &
         "those of load control (slower: MD takes tens of seconds).", &
         "", &
         "Columns:", &
         "  boundary      the code 100*which + 10*(mechanism below) + (mechanism above):", &
         "                which 1 full contact, 2 pull-off, 3 gap approach, 4 gap", &
         "                retraction (each code present is explained in the header)", &
         "  alpha mu      a point of the curve", &
         "The header lists each curve's start and end and the special points.", &
         "Common options: --model M, --format table|csv|json, --output FILE.", &
         "", &
         "Examples:", &
         "  wavyadhesion map --model dw", &
         "  wavyadhesion map --model dw --alpha 0.3,0.31 --control both --format json"]
      text = lines
   end function help_map

end module wa_cli_help
