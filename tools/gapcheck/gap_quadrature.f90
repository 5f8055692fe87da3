!> Prints W* (gap control) with the default quadrature (12 Gauss nodes per chain interval)
!> and with 20 nodes on halved intervals, and their relative difference, for the cases
!> quoted in doc/theory.md "Gap control":
!>   fpm run --profile release --example wavyadhesion-gapcheck
program gap_quadrature
   use wavyadhesion
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
end program gap_quadrature
