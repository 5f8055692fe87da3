!> Prints W* (gap control) with the default quadrature (16-node Gauss-Legendre panels)
!> and with 20-node panels on halved pieces, and their relative difference, for the cases
!> quoted in doc/theory.md "Gap control":
!>   cd study && fpm run --profile release wavyadhesion-gapcheck
!> With --sweep: gap_path for DW and MD over alpha in {0.01, 0.1, 0.3, 0.6, 1, 3, 10} x 31
!> log-spaced mu in [1e-3, 1e3]: failures, and the largest difference of the two rules.
program gap_quadrature
   use wavyadhesion
   use wa_kinds, only: wp
   use wa_gappath, only: gap_path_from_branch
   implicit none
   integer, parameter :: n = 12
   integer, parameter :: models(n) = [model_dw, model_dw, model_dw, model_md, model_md, &
      model_md, model_md, model_md, model_md, model_md, model_md, model_westergaard]
   real(wp), parameter :: alphas(n) = [0.3_wp, 0.3_wp, 1.0_wp, 0.3_wp, 0.3_wp, 1.0_wp, &
      0.6_wp, 0.1_wp, 1.0_wp, 0.01_wp, 3.0_wp, 0.3_wp]
   real(wp), parameter :: mus(n) = [1.0_wp, 0.1_wp, 5.0_wp, 1.0_wp, 5.0_wp, 1.0_wp, &
      1.0_wp, 3.0_wp, 0.3_wp, 0.251_wp, 30.0_wp, 1.0_wp]
   character(len=*), parameter :: names(0:3) = [character(len=11) :: "westergaard", "jkr", &
      "dw", "md"]
   type(params_type) :: params
   type(branch_type) :: b
   type(gap_path_type) :: p1, p2
   integer :: k, s1, s2, status
   real(wp) :: rel
   character(len=16) :: arg

   call get_command_argument(1, arg)
   if (arg == "--sweep") then
      call sweep()
      stop
   end if

   print '(a)', "# model alpha mu W*(12 nodes) W*(20 nodes, halved) relative_difference W*/(pi alpha^2/2)"
   do k = 1, n
      call new_params(alphas(k), mus(k), params, status)
      call trace_branch(models(k), params, b, status)
      call gap_path_from_branch(models(k), params, b, p1, s1)
      call gap_path_from_branch(models(k), params, b, p2, s2, nodes=20, splits=2)
      if (s1 /= wa_ok .or. s2 /= wa_ok) then
         print '(a,2g12.4,a)', trim(names(models(k))), alphas(k), mus(k), " failed"
         cycle
      end if
      rel = 0.0_wp
      if (p2%w_star /= 0.0_wp) rel = abs(p1%w_star/p2%w_star - 1.0_wp)
      print '(a12,1x,2es10.2,2es24.16,es10.2,es12.4)', trim(names(models(k))), alphas(k), mus(k), &
         p1%w_star, p2%w_star, rel, p1%w_fraction
   end do
contains

   subroutine sweep()
      real(wp), parameter :: alphas(7) = [0.01_wp, 0.1_wp, 0.3_wp, 0.6_wp, 1.0_wp, 3.0_wp, &
         10.0_wp]
      integer :: m, i, j, n_cases, n_trace_fail, n_fail
      real(wp) :: mu, worst, w_abs, worst_alpha, worst_mu
      integer :: worst_model
      print '(a)', "# gap_path sweep: model, cases, trace failures, gap_path failures, "// &
         "largest relative difference of the rules (absolute where W* < 1e-6)"
      do m = model_dw, model_md
         n_cases = 0; n_trace_fail = 0; n_fail = 0; worst = 0.0_wp
         worst_alpha = 0.0_wp; worst_mu = 0.0_wp; worst_model = m
         do i = 1, size(alphas)
            do j = 0, 30
               mu = 1.0e-3_wp*10.0_wp**(real(j, wp)/5.0_wp)
               n_cases = n_cases + 1
               call new_params(alphas(i), mu, params, status)
               call trace_branch(m, params, b, status)
               if (status /= wa_ok) then
                  n_trace_fail = n_trace_fail + 1
                  cycle
               end if
               call gap_path_from_branch(m, params, b, p1, s1)
               call gap_path_from_branch(m, params, b, p2, s2, nodes=20, splits=2)
               if (s1 /= wa_ok .or. s2 /= wa_ok) then
                  n_fail = n_fail + 1
                  print '(a,2es10.2,2i3)', "  failed: "//trim(names(m)), alphas(i), mu, s1, s2
                  cycle
               end if
               w_abs = max(abs(p2%w_star), 1.0e-6_wp)
               if (abs(p1%w_star - p2%w_star)/w_abs > worst) then
                  worst = abs(p1%w_star - p2%w_star)/w_abs
                  worst_alpha = alphas(i); worst_mu = mu
               end if
            end do
         end do
         print '(a,3(1x,i0),es10.2,a,2es10.2)', trim(names(m)), n_cases, n_trace_fail, n_fail, &
            worst, "  at alpha, mu =", worst_alpha, worst_mu
      end do
   end subroutine sweep

end program gap_quadrature
