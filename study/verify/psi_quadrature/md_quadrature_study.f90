!> Error against run time of the ways to compute Psi_c (2.27d) for the MD model.
!>
!> Reference: tools/reference/md_psi_reference.txt (mpmath, 32 digits, tools/reference/md_reference.py), 64
!> cases a* in {1e-12, 1e-6, 1e-3, 0.05, 0.25, 0.45, 1/2-1e-6, 1/2-1e-12} times
!> gap/(1/2-a*) in {1e-12, 1e-6, 0.01, 0.3, 0.7, 0.99, 1-1e-6, 1-1e-10}; "core" is the
!> subset a* in [1e-3, 0.45], gap/(1/2-a*) in [0.01, 0.99], "mid" the same with
!> gap/(1/2-a*) <= 0.7. Times are medians over the 64 cases and over the core cases
!> (best of 3 runs each).
!> gsl_fail counts the cases where GSL returned a non-zero status (its value is then
!> whatever it returned). GSL refuses epsrel < 50 eps = 1.1e-14 (epsabs = 0).
!> All methods integrate K = int_0^1 artanh(r) r G(r) dr,
!> G = 1/((1 - k^2 r^2) sqrt(1 - sin^2 s r^2)), Psi_c = -(2/pi) A q sin^2 s K:
!>   lib      the library's fixed graded Gauss rules (md_psi_c, src/wa_md_psi.f90; the time
!>            includes forming T, sin s, k from (a*, gap), about 0.1 us)
!>   gauss-N  one Gauss rule for the weight -ln(1-r) (N nodes) for -(1/2)ln(1-r) r G, plus
!>            N-point Gauss-Legendre for (1/2) ln(1+r) r G: singularity subtraction only
!>   qaws     GSL QAWS (weight ln(1-r)) + GSL QAG (GK21) for the ln(1+r) part, epsrel tol
!>   qag      GSL QAG (GK21) on the whole integrand, epsrel tol
!>   qags     GSL QAGS (extrapolating) on the whole integrand, epsrel tol
!> GSL workspaces and tables are allocated and freed per call, as a library would.
!> Run from the repository root: cd study && fpm run --profile release wavyadhesion-psi-quadrature
!> (or sh study/md_study.sh study).
program md_quadrature_study
   use, intrinsic :: iso_c_binding, only: c_funptr
   use, intrinsic :: iso_fortran_env, only: int64
   use wa_kinds, only: wp, pi
   use wa_md, only: md_psi_c
   use wa_gsl, only: gsl_set_error_handler_off
   use wa_quadrature, only: psi_gauss_rules, k_gauss, psi_k_gsl, sort2, quad_psi_qaws, &
      quad_psi_qag, quad_psi_qags
   implicit none

   integer, parameter :: max_cases = 200
   real(wp) :: a(max_cases), g(max_cases), ref(max_cases)
   integer :: n, u, ios
   character(len=200) :: line
   type(c_funptr) :: old
   !> Gauss rules of 16, 32, 64 nodes (psi_gauss_rules), built once
   real(wp) :: rule16(4, 16), rule32(4, 32), rule64(4, 64)

   old = gsl_set_error_handler_off()
   ! from the repository root, or from study/ (where the study's fpm package is)
   open (newunit=u, file="tools/reference/md_psi_reference.txt", status="old", action="read", &
      iostat=ios)
   if (ios /= 0) open (newunit=u, file="../tools/reference/md_psi_reference.txt", &
      status="old", action="read")
   n = 0
   do
      read (u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:1) == "#") cycle
      n = n + 1
      read (line, *) a(n), g(n), ref(n)
   end do
   close (u)

   call psi_gauss_rules(16, rule16)
   call psi_gauss_rules(32, rule32)
   call psi_gauss_rules(64, rule64)
   print '(a)', "# method        tol      max_err_all  max_err_core   max_err_mid  " &
      //"median_us  (core)  gsl_fail"
   call run("lib", 0, 0.0_wp)
   call run("gauss", 16, 0.0_wp)
   call run("gauss", 32, 0.0_wp)
   call run("gauss", 64, 0.0_wp)
   call run("qaws", 0, 1e-10_wp)
   call run("qaws", 0, 1e-12_wp)
   call run("qaws", 0, 1.2e-14_wp)
   call run("qag", 0, 1e-10_wp)
   call run("qag", 0, 1.2e-14_wp)
   call run("qags", 0, 1e-10_wp)
   call run("qags", 0, 1.2e-14_wp)

contains

   !> Max relative error (all cases, core cases) and median time per Psi_c of one method.
   subroutine run(method, nodes, tol)
      character(len=*), intent(in) :: method
      integer, intent(in) :: nodes
      real(wp), intent(in) :: tol
      real(wp) :: t(n), t_core(n), err_all, err_core, err_mid, v, e, frac
      integer :: i, r, reps, fails, st, dummy, n_core
      real(wp), volatile :: a_in, sink   ! keep every timed call
      integer(int64) :: c0, c1, rate
      character(len=16) :: label

      call system_clock(count_rate=rate)
      err_all = 0; err_core = 0; err_mid = 0; fails = 0; n_core = 0
      reps = merge(2000, 20, method == "lib" .or. method == "gauss")
      do i = 1, n
         t(i) = huge(1.0_wp)
         do r = 1, 3
            call system_clock(c0)
            a_in = a(i)
            do st = 1, reps
               sink = psi(method, nodes, tol, a_in, g(i), dummy)
            end do
            call system_clock(c1)
            t(i) = min(t(i), real(c1 - c0, wp)/real(rate, wp)/reps*1e6_wp)
         end do
         v = psi(method, nodes, tol, a(i), g(i), fails)
         e = abs(v - ref(i))/abs(ref(i))
         if (.not. (e == e)) e = huge(1.0_wp)
         err_all = max(err_all, e)
         frac = g(i)/(0.5_wp - a(i))
         if (a(i) >= 1e-3_wp .and. a(i) <= 0.45_wp .and. frac >= 0.01_wp .and. frac <= 0.99_wp) then
            err_core = max(err_core, e)
            n_core = n_core + 1
            t_core(n_core) = t(i)
         end if
         if (a(i) >= 1e-3_wp .and. a(i) <= 0.45_wp .and. frac >= 0.01_wp .and. frac <= 0.7_wp) &
            err_mid = max(err_mid, e)
      end do
      call sort(t)
      call sort(t_core(1:n_core))
      label = method
      if (nodes > 0) write (label, '(a,"-",i0)') method, nodes
      print '(a14, es9.1, 3es14.2, 2f11.3, i9)', label, tol, err_all, err_core, err_mid, &
         t((n + 1)/2), t_core((n_core + 1)/2), fails
   end subroutine run

   function psi(method, nodes, tol, a_star, gap, fails) result(v)
      character(len=*), intent(in) :: method
      integer, intent(in) :: nodes
      real(wp), intent(in) :: tol, a_star, gap
      integer, intent(inout) :: fails
      real(wp) :: v
      real(wp) :: aa, q, rm1, r, tt, sn, cs, kk, z(4)
      integer :: gsl_status

      if (method == "lib") then
         v = md_psi_c(a_star, gap)
         return
      end if
      aa = sin(pi*a_star)
      q = sin(pi*(0.5_wp - a_star))
      rm1 = sin(pi*gap)/(aa*sin(pi*((0.5_wp - a_star) - gap)))
      r = rm1 + 1.0_wp
      tt = sqrt(rm1*(rm1 + 2.0_wp))
      sn = tt/r
      cs = 1.0_wp/r
      kk = q*sn
      z = [kk**2, sn**2, cs**2 + (aa*sn)**2, cs**2]
      gsl_status = 0
      select case (method)
      case ("gauss")
         select case (nodes)
         case (16); v = k_gauss(z(1), z(2), z(3), z(4), rule16)
         case (32); v = k_gauss(z(1), z(2), z(3), z(4), rule32)
         case default; v = k_gauss(z(1), z(2), z(3), z(4), rule64)
         end select
      case ("qaws")
         call psi_k_gsl(quad_psi_qaws, z(1), z(2), z(3), z(4), tol, v, gsl_status)
      case ("qag")
         call psi_k_gsl(quad_psi_qag, z(1), z(2), z(3), z(4), tol, v, gsl_status)
      case default
         call psi_k_gsl(quad_psi_qags, z(1), z(2), z(3), z(4), tol, v, gsl_status)
      end select
      if (gsl_status /= 0) fails = fails + 1
      v = -(2.0_wp/pi)*aa*q*sn**2*v
   end function psi

   subroutine sort(t)
      real(wp), intent(inout) :: t(:)
      real(wp) :: x(size(t))
      x = t
      call sort2(t, x)
   end subroutine sort

end program md_quadrature_study
