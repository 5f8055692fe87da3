!> The wavyadhesion library: adhesive contact of a wavy elastic surface against a flat.
!> The umbrella module: `use wavyadhesion` gives the whole public API. Every name it
!> exports starts with a prefix of the library (wa_, model_, zone_, event_, ...) or names
!> a documented routine or type, so a host program can `use wavyadhesion` without `only:`
!> beside its own `wp`, `pi` or `status`; the real kind is `wa_wp`.
!>
!> Everything is dimensionless (doc/theory.md): a* = a/L and c* = c/L are the contact and
!> interaction-zone half-widths over the period L, P* the mean load over p* = pi E* Delta/L
!> (negative = tensile), gbar* the mean gap over the amplitude Delta. Every routine that
!> can fail returns a `status` (one of the wa_* codes below) and, where the caller passes
!> one, an `errmsg` naming the bad argument and its valid range.
!>
!> ## The public API
!>
!> Every name this module exports, by layer (test/docs/test_docs.py checks that this list
!> and the `public ::` statements name the same set).
!>
!> ### Parameters
!>
!> - [[wa_kinds:wp]] (exported as `wa_wp`): the real kind, C double, of every real argument.
!> - [[params_type]]: the dimensionless parameters alpha, mu and what derives from them (Sigma0, Dcod).
!> - [[scales_type]]: the SI scales that turn dimensionless results back into physical ones.
!> - [[new_params]]: validating constructor of a params_type from alpha and mu.
!> - [[dimensional_params]]: params_type and scales_type from SI inputs (E*, L, Delta, dgamma, sigma0).
!> - [[reduced_modulus]]: E* of two elastic bodies from their Young's moduli and Poisson ratios.
!> - [[wa_params:alpha_min]], [[wa_params:alpha_max]], [[wa_params:mu_min]],
!>   [[wa_params:mu_max]]: the accepted parameter domain.
!>
!> ### Kernels (closed forms, no solve)
!>
!> - [[westergaard_load]]: Westergaard (no adhesion) load P* = sin^2(pi a*).
!> - [[jkr_load]]: JKR load P* = sin^2(pi a*) - alpha sqrt(tan(pi a*)).
!> - [[westergaard_pressure]]: Westergaard contact pressure p/p* at x*.
!> - [[westergaard_displacement]]: Westergaard surface displacement u_z/Delta at x*.
!> - [[westergaard_gap]]: Westergaard gap h/Delta at x*.
!>
!> ### Models (equilibria at a given a*)
!>
!> - [[state_type]]: one equilibrium state (a*, c*, c* - a*, P*, zone case, gbar*).
!> - [[wa_state:model_westergaard]], [[wa_state:model_jkr]], [[wa_state:model_dw]],
!>   [[wa_state:model_md]]: the model codes.
!> - [[wa_state:zone_inside]], [[wa_state:zone_whole_period]], [[wa_state:zone_full_contact]],
!>   [[wa_state:zone_no_contact]]: the zone cases of a state.
!> - [[check_model]]: status of a model code (wa_invalid_argument if unknown).
!> - [[model_equilibrium]]: the principal equilibrium of any model at a*.
!> - [[model_roots]]: every equilibrium of any model at a*.
!> - [[model_state]]: the state of any model at a* with a given c*.
!> - [[model_profile]]: traction and gap profiles of the state model_state identifies.
!> - [[wa_models:state_c_tolerance]]: how close in c* model_state identifies a state.
!> - [[dw_equilibrium]]: the principal double-Westergaard (DW) equilibrium at a*.
!> - [[dw_roots]]: every DW equilibrium at a*.
!> - [[dw_traction]]: DW surface traction p/p* at x* of a solved state.
!> - [[dw_gap]]: DW gap h/Delta at x* of a solved state.
!> - [[dw_options]]: the numerical choices of dw_equilibrium (defaults: the library's).
!> - [[wa_dw:dw_istar_agm]], [[wa_dw:dw_istar_carlson]], [[wa_dw:dw_istar_tanh_sinh]],
!>   [[wa_dw:dw_istar_qag]]: dw_options' ways to compute the elliptic integral I*.
!> - [[md_equilibrium]]: the principal Maugis-Dugdale (MD) equilibrium at a*.
!> - [[md_roots]]: every MD equilibrium at a*.
!> - [[md_options]]: the numerical choices of md_equilibrium (defaults: the library's).
!> - [[md_prepare_options]]: check md_options and build the Gauss rules they ask for.
!> - [[wa_md_psi:md_psi_rules]], [[wa_md_psi:md_psi_gauss]], [[wa_md_psi:md_psi_qaws]],
!>   [[wa_md_psi:md_psi_qag]], [[wa_md_psi:md_psi_qags]]: md_options' ways to compute Psi_c.
!>
!> ### Separation (profiles and mean gap of a solved state)
!>
!> - [[state_profile]]: traction p/p* and gap h/Delta of a state at many x*, validated.
!> - [[state_traction]]: traction p/p* of a state at one x* (not validated).
!> - [[state_gap]]: gap h/Delta of a state at one x* (not validated).
!> - [[state_mean_gap]]: mean gap gbar* of a state, validated.
!> - [[check_state]]: status of a state (can it be a solved state of the model?).
!> - [[westergaard_mean_gap]]: Westergaard mean gap gbar* at a*.
!> - [[jkr_mean_gap]]: JKR mean gap gbar* at a*.
!> - [[dw_state_gbar]]: DW mean gap of a solved state.
!> - [[dw_mean_gap]]: DW mean gap from the quantities the DW solver has at hand.
!> - [[md_state_gbar]]: MD mean gap of a solved state.
!> - [[md_no_contact_state]]: the MD state without contact at a given zone half-width c*.
!> - [[md_no_contact_crest_gap]]: crest gap h(0)/Delta of that state.
!> - [[md_no_contact_closures]]: where the MD states without contact close (crest gap 0).
!> - [[md_no_contact_family]]: MD states without contact along one piece of their family.
!>
!> ### Branch (continuation in a*)
!>
!> - [[branch_type]]: a traced branch, its points in the order of the curve.
!> - [[trace_options]]: the continuation's controls (defaults suit every tested case).
!> - [[trace_branch]]: trace the equilibrium curve of a model from a* -> 0 to a* = 1/2.
!> - [[wa_branch:event_none]], [[wa_branch:event_fold]], [[wa_branch:event_switch]],
!>   [[wa_branch:event_jump_start]], [[wa_branch:event_jump_end]],
!>   [[wa_branch:event_full_contact_reached]], [[wa_branch:event_full_contact_left]],
!>   [[wa_branch:event_pull_off]], [[wa_branch:event_branch_end]],
!>   [[wa_branch:event_a_turn]]: the event codes of branch points and load-path events.
!>
!> ### Load control
!>
!> - [[path_type]]: the events of one loading-unloading cycle, in order.
!> - [[load_path]]: trace the branch, then load and unload along it.
!> - [[path_from_branch]]: load and unload along a branch already traced.
!> - [[critical_forces]]: full-contact load P_fc* and pull-off load P_pf* only.
!> - [[critical_sweep]]: P_fc*, P_pf* and their mechanisms for one alpha over many mu.
!> - [[mechanism_change]]: the mu where the full-contact or pull-off mechanism changes.
!> - [[wa_loadpath:stage_loading]], [[wa_loadpath:stage_unloading]]: the stages of a path.
!> - [[wa_loadpath:mechanism_gradual]], [[wa_loadpath:mechanism_jump_case1]],
!>   [[wa_loadpath:mechanism_jump_case2]], [[wa_loadpath:mechanism_snap]]: the mechanism codes.
!>
!> ### Gap control (mean-gap control)
!>
!> - [[gap_path_type]]: the events of one approach-retraction cycle, in order.
!> - [[gap_path]]: trace the branch, then approach and retract under gap control.
!> - [[gap_law]]: P* on approach and on retraction at given mean gaps.
!> - [[load_jump_energies]]: the energy released by each jump of a load-controlled path.
!> - [[wa_gappath:gap_stage_approach]], [[wa_gappath:gap_stage_retraction]]: the stages.
!> - [[wa_gappath:gap_event_touch]], [[wa_gappath:gap_event_contact_made]],
!>   [[wa_gappath:gap_event_contact_lost]], [[wa_gappath:gap_event_interaction_lost]]:
!>   the event codes of gap control (besides the branch's 3-6).
!> - [[gap_critical_type]]: the critical values of one gap-controlled cycle.
!> - [[gap_critical]]: trace the branch and return the critical values of its cycle.
!> - [[gap_critical_sweep]]: gap_critical for one alpha over many mu.
!> - [[gap_critical_values]]: the values of a gap_critical_type as an array.
!> - [[wa_gapcritical:gap_critical_count]], [[wa_gapcritical:gap_critical_names]]: how many
!>   values and their names, in order.
!> - [[gap_mechanisms]]: trace the branch and classify its gap-controlled cycle.
!> - [[gap_mechanism_change]]: the mu where the approach or retraction mechanism changes.
!> - [[gap_mechanism_name]]: the name of a gap-control mechanism code.
!>
!> ### Adhesion map
!>
!> - [[map_type]]: the map (grids, region mechanisms, boundary curves, special points).
!> - [[map_boundary]]: one boundary curve mu_b(alpha).
!> - [[map_point]]: one special point of the map.
!> - [[adhesion_map]]: build the map of a model over an alpha grid and a mu range.
!> - [[boundary_code]]: the code of a boundary from its mechanisms.
!> - [[boundary_meaning]]: a boundary code in words.
!> - [[special_meaning]]: a special point in words.
!> - [[wa_map_types:map_control_load]], [[wa_map_types:map_control_gap]],
!>   [[wa_map_types:map_control_both]]: which boundaries the map locates.
!> - [[wa_map_types:map_end_grid]], [[wa_map_types:map_end_inside]],
!>   [[wa_map_types:map_end_mu_range]], [[wa_map_types:map_end_failed]]: how a curve ends.
!> - [[wa_map_types:map_point_meet]], [[wa_map_types:map_point_turn]],
!>   [[wa_map_types:map_point_end]], [[wa_map_types:map_point_fail]]: the kinds of special point.
!>
!> ### Smooth adhesion (Lennard-Jones)
!>
!> - [[bem_law_type]], [[lj_law]]: the traction-gap law (LJ 3-9) in the library's units,
!>   from alpha and mu (same work of adhesion, range epsilon = the MD opening h0).
!> - [[lj_problem_type]], [[lj_problem]]: the discretised problem (grid of N points per
!>   period, automatic by default, profile: the sinusoid or samples of one period).
!> - [[lj_auto_n]], [[lj_zone_length]]: the automatic grid and the interaction-zone length
!>   it resolves; [[wa_bem_solver:lj_max_unknowns]], [[wa_bem_solver:lj_max_auto_n]]: the caps.
!> - [[lj_branch_type]], [[lj_trace_options]], [[lj_trace]]: the equilibrium curve from far
!>   apart to full contact by pseudo-arclength continuation, with stability under both controls.
!> - [[wa_bem_trace:lj_event_none]], [[wa_bem_trace:lj_event_load_fold]],
!>   [[wa_bem_trace:lj_event_gap_fold]], [[wa_bem_trace:lj_event_full_contact]],
!>   [[wa_bem_trace:lj_event_contact]], [[wa_bem_trace:lj_event_end]]: the curve's events.
!> - [[lj_path_type]], [[lj_cycle_type]], [[lj_paths]], [[lj_cycle]]: load- and
!>   gap-controlled paths, P_fc, P_pf, the snap-in load and W*, with N vs N/2 error estimates.
!> - [[wa_bem_path:lj_stage_loading]], [[wa_bem_path:lj_stage_unloading]],
!>   [[wa_bem_path:lj_stage_approach]], [[wa_bem_path:lj_stage_retraction]],
!>   [[wa_bem_path:lj_path_jump_start]], [[wa_bem_path:lj_path_jump_end]],
!>   [[wa_bem_path:lj_path_full_contact_reached]], [[wa_bem_path:lj_path_full_contact_left]],
!>   [[wa_bem_path:lj_path_pull_off]]: the stages and events of a path.
!> - [[lj_profile]]: the gap and traction of one state over the period.
!> - [[lj_state_type]], [[lj_state_at_a]]: the state at a given a* (the traced one with a*
!>   nearest it) with its gap and traction from x* = -1/2 (every face's LJ profile).
!> - [[lj_nearest_state]]: the traced state with a* nearest a target (among the load-stable
!>   states when there are any), the state a profile draws.
!> - [[lj_rigid_pull_off]]: the rigid-limit pull-off in closed form.
!>
!> ### Status and version
!>
!> - [[wa_status:wa_ok]], [[wa_status:wa_invalid_argument]], [[wa_status:wa_no_solution]],
!>   [[wa_status:wa_not_converged]], [[wa_status:wa_capacity_too_small]],
!>   [[wa_status:wa_numerical_error]]: the status codes every routine returns.
!> - [[status_message]]: a short description of a status code.
!> - [[wa_release:wa_version]]: the library's version, e.g. "0.2.0".
module wavyadhesion
   use wa_kinds, only: wa_wp => wp
   use wa_release, only: wa_version
   use wa_status, only: wa_ok, wa_invalid_argument, wa_no_solution, wa_not_converged, &
      wa_capacity_too_small, wa_numerical_error, status_message
   use wa_params, only: params_type, scales_type, new_params, dimensional_params, &
      reduced_modulus, alpha_min, alpha_max, mu_min, mu_max
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact, &
      zone_no_contact, model_westergaard, model_jkr, model_dw, model_md
   use wa_kernels, only: westergaard_load, jkr_load, westergaard_pressure, &
      westergaard_displacement, westergaard_gap
   use wa_dw, only: dw_equilibrium, dw_roots, dw_traction, dw_gap, dw_options, dw_istar_agm, &
      dw_istar_carlson, dw_istar_tanh_sinh, dw_istar_qag
   use wa_md, only: md_equilibrium, md_roots, md_options, md_prepare_options
   use wa_md_psi, only: md_psi_rules, md_psi_gauss, md_psi_qaws, md_psi_qag, md_psi_qags
   use wa_models, only: check_model, model_equilibrium, model_roots, model_state, &
      model_profile, state_c_tolerance
   use wa_separation, only: westergaard_mean_gap, jkr_mean_gap, dw_state_gbar, &
      md_state_gbar, dw_mean_gap, state_mean_gap, state_profile, state_traction, state_gap, check_state
   use wa_md_nocontact, only: md_no_contact_crest_gap, md_no_contact_state, &
      md_no_contact_closures, md_no_contact_family
   use wa_branch_types, only: branch_type, trace_options
   use wa_branch, only: trace_branch, event_none, event_fold, event_switch, &
      event_jump_start, event_jump_end, event_full_contact_reached, &
      event_full_contact_left, event_pull_off, event_branch_end, event_a_turn
   use wa_loadpath, only: path_from_branch
   use wa_loadpath, only: path_type, load_path, critical_forces, critical_sweep, &
      mechanism_change, stage_loading, stage_unloading, mechanism_gradual, &
      mechanism_jump_case1, mechanism_jump_case2, mechanism_snap
   use wa_map_types, only: map_type, map_boundary, boundary_code, boundary_meaning, &
      map_end_grid, map_end_inside, map_end_mu_range, map_end_failed, map_point, &
      special_meaning, map_point_meet, map_point_turn, map_point_end, map_point_fail
   use wa_map, only: adhesion_map
   use wa_gappath, only: gap_path_type, gap_path, gap_law, gap_stage_approach, gap_stage_retraction, &
      gap_event_touch, gap_event_contact_made, gap_event_contact_lost, &
      gap_event_interaction_lost
   use wa_jump_energy, only: load_jump_energies
   use wa_gapcritical, only: gap_critical_type, gap_critical, gap_critical_sweep, &
      gap_critical_values, gap_critical_count, gap_critical_names
   use wa_map_types, only: map_control_load, map_control_gap, map_control_both
   use wa_gapmech, only: gap_mechanisms, gap_mechanism_change, gap_mechanism_name
   use wa_bem_law, only: bem_law_type, lj_law
   use wa_bem_solver, only: lj_problem_type, lj_problem, lj_auto_n, lj_zone_length, &
      lj_max_unknowns, lj_max_auto_n
   use wa_bem_path, only: lj_path_type, lj_cycle_type, lj_paths, lj_cycle, lj_rigid_pull_off, &
      lj_stage_loading, &
      lj_stage_unloading, lj_stage_approach, lj_stage_retraction, lj_path_jump_start, &
      lj_path_jump_end, lj_path_full_contact_reached, lj_path_full_contact_left, lj_path_pull_off
   use wa_bem_trace, only: lj_branch_type, lj_trace_options, lj_trace, &
      lj_event_none, &
      lj_event_load_fold, lj_event_gap_fold, lj_event_full_contact, lj_event_contact, lj_event_end
   use wa_bem_state, only: lj_state_type, lj_state_at_a, lj_nearest_state, lj_profile
   implicit none
   private

   !> The library's real kind (C double): declare reals as real(wa_wp) to pass them unchanged.
   public :: wa_wp
   public :: load_jump_energies
   public :: gap_path_type, gap_path, gap_law, gap_stage_approach, gap_stage_retraction, &
      gap_event_touch, gap_event_contact_made, gap_event_contact_lost, &
      gap_event_interaction_lost
   public :: wa_ok, wa_invalid_argument, wa_no_solution, wa_not_converged, &
      wa_capacity_too_small, wa_numerical_error, status_message
   public :: params_type, scales_type, new_params, dimensional_params, reduced_modulus
   public :: alpha_min, alpha_max, mu_min, mu_max
   public :: state_type, zone_inside, zone_whole_period, zone_full_contact
   public :: model_westergaard, model_jkr, model_dw, model_md
   public :: westergaard_load, jkr_load, westergaard_pressure, westergaard_displacement, &
      westergaard_gap
   public :: dw_equilibrium, dw_roots, dw_traction, dw_gap
   public :: dw_options, dw_istar_agm, dw_istar_carlson, dw_istar_tanh_sinh, dw_istar_qag
   public :: md_equilibrium, md_roots
   public :: md_options, md_prepare_options, md_psi_rules, md_psi_gauss, md_psi_qaws, &
      md_psi_qag, md_psi_qags
   public :: check_model, model_equilibrium, model_roots, model_state, model_profile, &
      state_c_tolerance
   public :: westergaard_mean_gap, jkr_mean_gap, dw_state_gbar, md_state_gbar, dw_mean_gap, &
      state_mean_gap, state_profile, state_traction, state_gap, check_state, &
      md_no_contact_crest_gap, md_no_contact_state, md_no_contact_closures, &
      md_no_contact_family, zone_no_contact
   public :: branch_type, trace_options, trace_branch, event_none, event_fold, event_switch, &
      event_jump_start, event_jump_end, event_full_contact_reached, event_full_contact_left, &
      event_pull_off, event_branch_end, event_a_turn
   public :: path_from_branch
   public :: path_type, load_path, critical_forces, critical_sweep, mechanism_change, &
      stage_loading, stage_unloading, mechanism_gradual, mechanism_jump_case1, &
      mechanism_jump_case2, mechanism_snap
   public :: map_type, map_boundary, adhesion_map, boundary_code, boundary_meaning, &
      map_end_grid, map_end_inside, map_end_mu_range, map_end_failed, map_point, &
      special_meaning, map_point_meet, map_point_turn, map_point_end, map_point_fail

   public :: wa_version
   public :: gap_critical_type, gap_critical, gap_critical_sweep, gap_critical_values, &
      gap_critical_count, gap_critical_names
   public :: map_control_load, map_control_gap, map_control_both
   public :: gap_mechanisms, gap_mechanism_change, gap_mechanism_name
   public :: bem_law_type, lj_law
   public :: lj_problem, lj_auto_n, lj_zone_length, lj_max_unknowns, lj_max_auto_n
   public :: lj_path_type, lj_cycle_type, lj_paths, lj_cycle, lj_rigid_pull_off, &
      lj_profile, lj_stage_loading, &
      lj_stage_unloading, lj_stage_approach, lj_stage_retraction, lj_path_jump_start, &
      lj_path_jump_end, lj_path_full_contact_reached, lj_path_full_contact_left, lj_path_pull_off
   public :: lj_problem_type, lj_branch_type, lj_trace_options, lj_trace, lj_nearest_state, &
      lj_event_none, &
      lj_event_load_fold, lj_event_gap_fold, lj_event_full_contact, lj_event_contact, lj_event_end
   public :: lj_state_type, lj_state_at_a

end module wavyadhesion
