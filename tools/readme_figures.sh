#!/usr/bin/env bash
# Reproduces every number, table and picture of the README in one go: trainer speed and trades,
# table accuracy, the per-scene comparison tables, the bench (tables, Pareto and pass plots,
# crops), the papers' figures, the coverage family's goals on held-out models, the
# scene-specific tables and the reliability report. Logs go to
# OUT_DIR/*.md; the pictures the README shows are copied to docs/images/.
# Usage: tools/readme_figures.sh [--quick] [--only papers|cost|diagnosis|coverage|goals] [OUT_DIR]
#   --quick: CI scale (small images, few cases and frames, under 2 minutes); it checks that every
#            step runs and leaves docs/ alone. Default OUT_DIR: out/figures (out/figures-quick).
#   --only papers: just the papers' figures (rsaa figures, about 4 minutes; with --quick: seconds).
#   --only cost: just the timing steps (post-process at 1280x720, the culled pre-pass, the
#            multisample pre-pass and the union pattern, the cell patterns, how cost grows, the
#            bench; about 16 minutes), to measure them again on a quiet machine.
#   --only diagnosis: just the rsaa diagnose steps (about 6 minutes).
#   --only coverage: just the coverage family's goals and scale tests (about 30 minutes).
#   --only goals: just RSAA's goals (issue 11) on the bench scenes and held-out models, facet
#            edges and borrowed colours on them, and 53 surveyed models (about 50 minutes: the
#            facet-edges and survey steps took 580 and 733 s in session 26).
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
only=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --quick) quick=1; shift ;;
    --only) only=${2:?--only needs a step: papers, cost, diagnosis, coverage or goals}; shift 2 ;;
    -h | --help) sed -n 2,17p "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) break ;;
  esac
done
[[ -z $only || $only == papers || $only == cost || $only == diagnosis || $only == coverage || $only == goals ]] ||
  { echo "readme_figures.sh: --only $only: the steps run alone are: papers, cost, diagnosis, coverage, goals" >&2; exit 2; }
[[ $only != cost && $only != diagnosis && $only != coverage && $only != goals || $quick == 0 ]] ||
  { echo "readme_figures.sh: --only $only has no --quick form" >&2; exit 2; }
default_out=out/figures
[[ $quick == 1 ]] && default_out=out/figures-quick
out=${1:-$default_out}
mkdir -p "$out" "$out/diagnosis"
rsaa=./build/rsaa
[[ -x $rsaa ]] || bash tools/build.sh
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
truck=/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf
step() { echo "== $1 -> $out/$2" >&2; }
models=/usr/share/assimp/models
# 13 more held-out models for RSAA's and the coverage family's goals (a sweep of other formats after
# the shading fix).
more_models=($models/FBX/cubes_with_mirroring_and_pivot.fbx $models/STL/3DSMaxExport.STL
  $models/LWO/LWO2/hierarchy_smoothed.lwo $models/AC/SphereWithLight.ac $models/MD2/faerie.md2
  $models/X/BCN_Epileptic.X $models/Ogre/TheThing/Mesh.mesh.xml $models/HMP/terrain.hmp $models/SIB/heffalump.sib
  $models/SMD/holy_grailref.smd $models/NFF/NFF/spheres.nff $models/3MF/box.3mf $models/XGL/sample_official.xgl)
# 53 more held-out model files that load (session 24's survey: every format directory, detailed
# models first; the failures to load are listed in the README): RSAA's goals step on them.
survey_models=($models/3DS/test1.3ds $models/AC/Wuson.ac $models/AC/sample_subdiv.ac
  $models/ASE/MotionCaptureROM.ase $models/ASE/anim2.ASE $models/B3D/WusonBlitz.b3d
  $models/BLEND/Suzanne_248.blend $models/BLEND/TorusLightsCams_250_compressed.blend
  $models/BLEND/blender_269_regress1.blend $models/BLEND/test_279.blend $models/BLEND/yxa_1.blend
  $models/COB/spider_4_3.cob $models/Collada/COLLADA.dae $models/Collada/Cinema4D.dae
  $models/Collada/anims_with_full_rotations_between_keys.DAE $models/Collada/earthCylindrical.DAE
  $models/Collada/human.zae $models/Collada/kwxport_test_vcolors.dae $models/Collada/regr01.dae
  $models/Collada/teapot_instancenodes.DAE $models/DXF/PinkEggFromLW.dxf $models/DXF/issue_2229.dxf
  $models/DXF/wuson.dxf $models/FBX/animation_with_skeleton.fbx $models/FBX/huesitos.fbx
  $models/FBX/spider.fbx $models/LWO/LWO2/MappingModes/earth_uv_cylindrical_y.lwo
  $models/LWO/LWO2/ModoExport_vertNormals.lwo $models/LWO/LWO2/UglyVertexColors.lwo
  $models/LWO/LXOB_Modo/CrazyEngine.lxo $models/MD2/sydney.md2 $models/MDC/spider.mdc
  "$models/MDL/MDL (HL1)/man.mdl" "$models/MDL/MDL3 (3DGS A4)/minigun.MDL"
  "$models/MDL/MDL5 (3DGS A5)/minigun_mdl5.mdl" "$models/MDL/MDL7 (3DGS A7)/PhosphoricAcid_MDl7.mdl"
  $models/MS3D/twospheres_withmats.ms3d $models/OFF/Wuson.off $models/OpenGEX/collada.ogex
  $models/Q3D/earth.q3o $models/RAW/Wuson.raw $models/SMD/WusonSMD.smd $models/STL/Spider_binary.stl
  $models/STL/sphereWithHole.stl $models/X/Testwuson.X $models/X/anim_test.x $models/X/fromtruespace_bin32.x
  $models/X3D/HelloX3dTrademark.x3d $models/XGL/BCN_Epileptic.zgl $models/XGL/Spider_ascii.zgl
  $models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf $models/glTF2/simple_skin/simple_skin.gltf
  $models/glTF2/textureTransform/TextureTransformTest.gltf)
# Held-out models surveyed in session 24 where RSAA 8x lost to 4x MSAA by more than 0.1 dB, or where
# facet edges change the most (flat-shaded meshes among them): the facet-edges step.
facet_models=($models/FBX/animation_with_skeleton.fbx $models/STL/sphereWithHole.stl
  $models/LWO/LWO2/MappingModes/earth_uv_cylindrical_y.lwo $models/STL/Spider_binary.stl $models/X/Testwuson.X
  $models/DXF/issue_2229.dxf $models/LWO/LXOB_Modo/CrazyEngine.lxo $models/3DS/test1.3ds $models/Collada/regr01.dae
  $models/Collada/COLLADA.dae $models/STL/3DSMaxExport.STL $models/ASE/anim2.ASE)
started=$SECONDS

# The papers' figures (rsaa figures): RSAA's Figures 9 and 1, DCAA's and AGAA's sweeps, memory.
papers_figures() {
  step "the papers' figures" papers.md
  if [[ $quick == 1 ]]; then
    $rsaa figures --quick --out-dir "$out/papers" >"$out/papers.md"
    return
  fi
  $rsaa figures --out-dir "$out/papers" >"$out/papers.md"
  for f in fig9 fig1-default fig1-2CylinderEngine dcaa-histogram dcaa-surfaces agaa memory; do
    cp "$out/papers/$f.png" "docs/images/papers_$f.png"
  done
}
# Cost at the sizes engines run (the post-process as multiples of a copy pass), how it grows, the
# bench: the steps whose figures are timings.
cost_steps() {
  step "post-process at 1280x720" post-1280.md
  $rsaa bench --scenes builtin:default --width 1280 --height 720 --frames 3 --orbit-frames 2 \
    --techniques "fxaa,msaa 4x,rsaa 8x sadp-plane auth0,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe edges-pass,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe single-pass,rsaa 4x gl4x sadp-plane auth1 cap1.5 mb sc fc me fe" \
    --out-dir "$out/post-1280" >"$out/post-1280.md"
  step "the culled pre-pass at 1280x720" prepass-cull.md
  $rsaa bench --scenes "builtin:default,$engine,$truck,/usr/share/assimp/models/OBJ/spider.obj,builtin:fence" \
    --width 1280 --height 720 --frames 3 --orbit-frames 2 \
    --techniques "rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe,rsaa 8x sadp-plane auth1 jittered cap1.5 mb sc fc me fe,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe cull" \
    --out-dir "$out/prepass-cull" >"$out/prepass-cull.md"
  step "multisample pre-pass and the union pattern (8 subsamples as two 4x draws)" prepass-union.md
  { for t in custom-gl4x-union d3d8x gl4x; do $rsaa eval-table tables/$t.json 2>/dev/null; done
    $rsaa bench --scenes "builtin:default,$engine,$truck,/usr/share/assimp/models/OBJ/spider.obj" \
      --techniques "msaa 4x,rsaa 4x gl4x sadp-plane auth1 cap1.5 mb sc fc me fe,rsaa 4x gl4x sadp-plane auth1 jittered cap1.5 mb sc fc me fe,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe,rsaa 8x sadp-plane auth1 jittered cap1.5 mb sc fc me fe" \
      --table tables/custom-gl4x-union.json --table-prepass both --out-dir "$out/prepass-union"; } >"$out/prepass-union.md"
  step "cell patterns: 8 (16) subsamples from one 4x draw at twice the height (and width), what RSAA adds" cell-patterns-cost.md
  { $rsaa bench --scenes "builtin:default,$engine,$truck,/usr/share/assimp/models/OBJ/spider.obj" --orbit-frames 2 \
      --techniques "msaa 4x,rsaa 4x gl4x sadp-plane auth1 cap1.5 mb sc fc me fe,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe" \
      --table tables/custom-gl4x-tall.json --out-dir "$out/cell-patterns-cost"
    $rsaa bench --scenes builtin:default --width 1280 --height 720 --frames 3 --orbit-frames 2 \
      --techniques "msaa 4x,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe" --table tables/custom-gl4x-tall.json \
      --out-dir "$out/cell-patterns-cost-1280"
    $rsaa bench --growth --techniques "msaa 4x,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe" \
      --table tables/custom-gl4x-tall.json --out-dir "$out/cell-patterns-growth"
    # 16 subsamples from one 4x draw at twice the width and height.
    $rsaa bench --scenes "builtin:default,$engine,$truck,/usr/share/assimp/models/OBJ/spider.obj" --orbit-frames 2 \
      --techniques "msaa 4x,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe" --table tables/custom-gl4x-quad.json \
      --out-dir "$out/cell-patterns-cost-quad"
    $rsaa bench --scenes builtin:default --width 1280 --height 720 --frames 3 --orbit-frames 2 \
      --techniques "msaa 4x,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe" --table tables/custom-gl4x-quad.json \
      --out-dir "$out/cell-patterns-cost-quad-1280"; } >"$out/cell-patterns-cost.md"
  cp "$out/cell-patterns-growth/growth-lights.png" docs/images/cell_patterns_lights.png
  step "how cost grows: image size, triangles, lights" growth.md
  $rsaa bench --growth --out-dir "$out/growth" \
    --techniques "fxaa,msaa 4x,ssaa 8x,dyncov,dcaa,agaa 8x,rsaa 4x gl4x sadp-plane auth1 cap1.5 mb sc fc me fe,rsaa 4x gl4x sadp-plane auth1 jittered cap1.5 mb sc fc me fe,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe,rsaa 8x sadp-plane auth1 jittered cap1.5 mb sc fc me fe,rsaa 8x sadp-plane auth0" \
    --table tables/custom-gl4x-union.json --table-prepass msaa >"$out/growth.md"
  for axis in pixels triangles lights; do cp "$out/growth/growth-$axis.png" "docs/images/growth_$axis.png"; done
  step "bench" bench.md
  $rsaa bench --target-psnr 38 --out-dir "$out/bench" >"$out/bench.md"
  cp "$out/bench/pareto-default.png" docs/images/bench_pareto_default.png
  cp "$out/bench/passes-default.png" docs/images/bench_passes_default.png
  cp "$out/bench/pareto-2CylinderEngine.png" docs/images/bench_pareto_engine.png
  cp "$out/bench/crops-default.png" docs/images/bench_crops_default.png
  cp "$out/bench/crops-2CylinderEngine.png" docs/images/bench_crops_engine.png
}
# Where RSAA's error lives (rsaa diagnose): before and after on three scenes, the defaults at 8 and
# 4 subsamples, and the held-out models where RSAA 8x stays below 4x MSAA (about 6 minutes).
diagnosis_steps() {
  for scene in builtin:default "$engine" builtin:grazing; do
    name=$(basename "${scene#builtin:}"); name=${name%.*}
    # Before (the paper's SADP, then sadp-plane, each with the paper's resolve) and after (the defaults).
    for variant in sadp sadp-plane defaults; do
      options=(--similarity "$variant" --auth 0 --split-cap 0 --multi-surface fetch --split-check off --fetch-check off
               --material-edges off)
      [ "$variant" = defaults ] && options=()
      step "diagnosis, $name, $variant" "diagnosis/$name-$variant.md"
      $rsaa diagnose --scene "$scene" "${options[@]}" --out-dir "$out/diagnosis/$name-$variant" \
        >"$out/diagnosis/$name-$variant.md"
      cp "$out/diagnosis/$name-$variant/error_map.png" "docs/images/diagnosis_${name}_$variant.png"
    done
  done
  # Why 8 subsamples gain little over 4: the defaults at both counts, per class, beside exact coverage.
  for scene in builtin:default "$engine" "$truck" /usr/share/assimp/models/OBJ/spider.obj; do
    name=$(basename "${scene#builtin:}"); name=${name%.*}
    for samples in 8 4; do
      step "diagnosis, $name, defaults at ${samples}x" "diagnosis/$name-samples$samples.md"
      $rsaa diagnose --scene "$scene" --samples $samples --out-dir "$out/diagnosis/$name-samples$samples" \
        >"$out/diagnosis/$name-samples$samples.md"
    done
  done
  step "why 8 subsamples gain about 1 dB over 4 (the README's table, from the diagnoses above)" why8.md
  bash tools/why8_table.sh "$out/diagnosis" default 2CylinderEngine CesiumMilkTruck spider >"$out/why8.md"
  for scene in $models/Q3D/E-AT-AT.q3o $models/3DS/fels.3ds $models/COB/dwarf.cob $models/IFC/AC14-FZK-Haus.ifc; do
    name=$(basename "$scene"); name=${name%.*}
    step "diagnosis, $name (held out), defaults" "diagnosis/$name-defaults.md"
    $rsaa diagnose --scene "$scene" --out-dir "$out/diagnosis/$name-defaults" >"$out/diagnosis/$name-defaults.md"
  done
}
# The coverage family's goals (issue 14): held-out models with the scale test (about 16 minutes),
# 13 more (3 minutes), the bench scenes (the *Quality* table and the "bench:" scale rows).
coverage_steps() {
  # The coverage family's goals and the scale test on held-out models (issue 14; about 16 minutes).
  step "coverage goals on held-out models" coverage-goals.md
  bash tools/coverage_goals.sh --scale --out-dir "$out/coverage-goals" $models/3DS/fels.3ds $models/OBJ/WusonOBJ.obj \
    $models/Collada/duck.dae $models/IFC/AC14-FZK-Haus.ifc $models/Q3D/E-AT-AT.q3o $models/MS3D/jeep1.ms3d \
    $models/COB/dwarf.cob $models/BLEND/SuzanneSubdiv_252.blend $models/IQM/mrfixit.iqm \
    $models/X3D/ComputerKeyboard.x3d >"$out/coverage-goals.md"
  # The same goals on the 13 more held-out models of RSAA's goals (no scale test; about 3 minutes).
  step "coverage goals on 13 more held-out models" coverage-goals-more.md
  bash tools/coverage_goals.sh --out-dir "$out/coverage-goals-more" "${more_models[@]}" >"$out/coverage-goals-more.md"
  # The same goals on the bench's scenes (the coverage family's *Quality* table) and the scale test
  # on the default scene and the three bench models (the "bench:" rows of the scale table).
  step "coverage goals on the bench scenes" coverage-goals-bench.md
  { bash tools/coverage_goals.sh --out-dir "$out/coverage-goals-bench" builtin:default builtin:distant builtin:edges \
      builtin:fence builtin:interpenetrating builtin:star builtin:grazing builtin:coplanar "$engine" "$truck" \
      $models/OBJ/spider.obj
    bash tools/coverage_goals.sh --scale --out-dir "$out/coverage-goals-bench-scale" builtin:default "$engine" "$truck" \
      $models/OBJ/spider.obj; } >"$out/coverage-goals-bench.md"
}
# RSAA's goals (issue 11) on the bench scenes, the coplanar scene and held-out models, with what the
# latest default (material edges) changed; crops of the coplanar scene.
goals_steps() {
  # The goals' 25 scenes: the bench's, the coplanar scene and 14 held-out models.
  local goal_scenes=(builtin:default builtin:grazing builtin:edges builtin:star builtin:fence builtin:distant
    builtin:interpenetrating builtin:coplanar "$engine" "$truck" $models/OBJ/spider.obj $models/OBJ/WusonOBJ.obj
    $models/3DS/fels.3ds $models/Collada/duck.dae $models/Collada/teapots.DAE $models/MS3D/jeep1.ms3d
    $models/X3D/ComputerKeyboard.x3d $models/Q3D/E-AT-AT.q3o $models/COB/dwarf.cob $models/X/BCN_Epileptic.X
    $models/IFC/AC14-FZK-Haus.ifc $models/COB/molecule.cob $models/Ogre/TheThing/Mesh.mesh.xml
    $models/BLEND/HUMAN.blend $models/glTF2/BoxTextured-glTF/BoxTextured.gltf)
  step "RSAA's goals, material edges off -> on" rsaa-goals.md
  bash tools/rsaa_goals.sh --out-dir "$out/rsaa-goals" --without "--material-edges off" "${goal_scenes[@]}" \
    >"$out/rsaa-goals.md"
  bash tools/crops.sh "$out/rsaa-goals/coplanar" 120x90+190+130 docs/images/coplanar_crops.png \
    noaa rsaasamples8-without rsaasamples8 msaasamples4 reference
  step "cell patterns against d3d8x, the union and d3d16x (images, line cases)" cell-patterns.md
  bash tools/cell_patterns.sh --out-dir "$out/cell-patterns" "${goal_scenes[@]}" >"$out/cell-patterns.md"
  step "cell patterns: the README's summary (from cell-patterns.md)" cell-patterns-summary.md
  bash tools/cell_patterns_summary.sh "$out/cell-patterns/cell-patterns.md" >"$out/cell-patterns-summary.md"
  step "cell patterns on 13 more held-out models and mrfixit" cell-patterns-more.md
  bash tools/cell_patterns.sh --out-dir "$out/cell-patterns-more" "${more_models[@]}" $models/IQM/mrfixit.iqm \
    >"$out/cell-patterns-more.md"
  step "RSAA's goals on 13 more held-out models" rsaa-goals-more.md
  bash tools/rsaa_goals.sh --out-dir "$out/rsaa-goals-more" "${more_models[@]}" >"$out/rsaa-goals-more.md"
  step "RSAA without and with facet edges (--facet-edges off -> defaults): the goals' scenes and held-out models" facet-edges.md
  bash tools/rsaa_goals.sh --out-dir "$out/facet-edges" --without "--facet-edges off" "${goal_scenes[@]}" \
    $models/IQM/mrfixit.iqm "${facet_models[@]}" >"$out/facet-edges.md"
  bash tools/crops.sh "$out/facet-edges/sphereWithHole" 100x75+330+250 docs/images/facet_crops.png \
    noaa rsaasamples8-without rsaasamples8 msaasamples4 reference
  step "RSAA without and with borrowed colours (--multi-surface neighbours -> defaults): the same scenes" borrowed-colours.md
  bash tools/rsaa_goals.sh --out-dir "$out/borrowed-colours" --without "--multi-surface neighbours" "${goal_scenes[@]}" \
    $models/IQM/mrfixit.iqm "${facet_models[@]}" >"$out/borrowed-colours.md"
  bash tools/crops.sh "$out/borrowed-colours/AC14-FZK-Haus" 50x60+235+280 docs/images/borrow_crops.png \
    noaa rsaasamples8-without rsaasamples8 msaasamples4 reference
  step "borrowed colours: the mean alone -> the mean blended with the fetch where only a far source calls for it (--borrow-weight 1 -> defaults)" borrow-weight.md
  bash tools/rsaa_goals.sh --out-dir "$out/borrow-weight" --without "--borrow-weight 1" "${goal_scenes[@]}" \
    $models/IQM/mrfixit.iqm "${facet_models[@]}" >"$out/borrow-weight.md"
  step "RSAA's goals on 53 surveyed held-out models (--facet-edges off -> defaults)" rsaa-goals-survey.md
  bash tools/rsaa_goals.sh --out-dir "$out/rsaa-goals-survey" --without "--facet-edges off" "${survey_models[@]}" \
    >"$out/rsaa-goals-survey.md"
}
if [[ $only == cost ]]; then
  cost_steps
  echo "the timing steps done in $((SECONDS - started)) s" >&2
  exit 0
fi
if [[ $only == diagnosis ]]; then
  diagnosis_steps
  echo "the diagnosis steps done in $((SECONDS - started)) s" >&2
  exit 0
fi
if [[ $only == coverage ]]; then
  coverage_steps
  echo "the coverage steps done in $((SECONDS - started)) s" >&2
  exit 0
fi
if [[ $only == goals ]]; then
  goals_steps
  echo "RSAA's goals done in $((SECONDS - started)) s" >&2
  exit 0
fi
if [[ $only == papers ]]; then
  papers_figures
  echo "the papers' figures done in $((SECONDS - started)) s" >&2
  exit 0
fi

if [[ $quick == 1 ]]; then
  step "table accuracy (10^4 cases)" eval-table.md
  for t in d3d4x d3d8x; do $rsaa eval-table tables/$t.json --cases 10000 --seed 2; done >"$out/eval-table.md"
  step "fit trade (10^4 cases)" fit-trade.md
  bash tools/fit_trade.sh d3d8x 10000 >"$out/fit-trade.md"
  step "training time (10^5 cases, 1 run)" train-speed.md
  bash tools/bench_train.sh d3d8x 100000 1 >"$out/train-speed.md"
  step "compare variants, default scene at 160x120" compare-default.md
  bash tools/compare_variants.sh builtin:default 160 120 "$out/compare/default" >"$out/compare-default.md"
  step "diagnosis, edges at 160x120" diagnosis.md
  $rsaa diagnose --scene builtin:edges --width 160 --height 120 --surface-samples 4 --out-dir "$out/diagnosis" \
    >"$out/diagnosis.md"
  step "why 8 subsamples gain about 1 dB over 4, edges at 160x120" why8.md
  $rsaa diagnose --scene builtin:edges --width 160 --height 120 --surface-samples 4 --samples 4 \
    --out-dir "$out/diagnosis/edges-samples4" >"$out/diagnosis/edges-samples4.md"
  cp "$out/diagnosis.md" "$out/diagnosis/edges-samples8.md"
  bash tools/why8_table.sh "$out/diagnosis" edges >"$out/why8.md"
  step "coverage goals, default scene at 160x120" coverage-goals.md
  bash tools/coverage_goals.sh --width 160 --height 120 --out-dir "$out/coverage-goals" builtin:default \
    >"$out/coverage-goals.md"
  step "RSAA's goals, material edges off -> on, coplanar scene at 160x120" rsaa-goals.md
  bash tools/rsaa_goals.sh --width 160 --height 120 --out-dir "$out/rsaa-goals" --without "--material-edges off" \
    builtin:coplanar >"$out/rsaa-goals.md"
  step "cell patterns, default scene at 160x120 (10^4 cases)" cell-patterns.md
  bash tools/cell_patterns.sh --width 160 --height 120 --cases 10000 --out-dir "$out/cell-patterns" builtin:default \
    >"$out/cell-patterns.md"
  bash tools/cell_patterns_summary.sh "$out/cell-patterns/cell-patterns.md" >"$out/cell-patterns-summary.md"
  step "bench --quick" bench/report.md
  $rsaa bench --quick --target-psnr 30 --out-dir "$out/bench" >"$out/bench.md"
  step "bench --growth --quick" growth.md
  $rsaa bench --growth --quick --techniques "msaa 4x,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe" \
    --out-dir "$out/growth" >"$out/growth.md"
  papers_figures
  echo "quick figures done in $((SECONDS - started)) s; docs/ untouched" >&2
  exit 0
fi

step "training time" train-speed.md
{ bash tools/bench_train.sh; bash tools/bench_train.sh d3d16x 1000000 1; bash tools/bench_train.sh d3d8x 10000000 1
  bash tools/bench_train.sh d3d16x 100000000 1; } \
  >"$out/train-speed.md"
step "fit trade" fit-trade.md
bash tools/fit_trade.sh >"$out/fit-trade.md"
step "trainer trades" trainer-trades.md
bash tools/trainer_trades.sh builtin:default "$out/trainer-trades" >"$out/trainer-trades.md"
cp "$out/trainer-trades/cases.png" docs/images/trades_cases.png
cp "$out/trainer-trades/threshold.png" docs/images/trades_threshold.png
step "table accuracy" eval-table.md
$rsaa eval-table tables/d3d8x.json >"$out/eval-table.md"
for scene in builtin:default "$engine" "$truck"; do
  name=$(basename "${scene#builtin:}"); name=${name%.*}
  step "compare variants, $name" "compare-$name.md"
  bash tools/compare_variants.sh "$scene" 640 480 "$out/compare/$name" >"$out/compare-$name.md"
done
cp "$out/compare/default/rsaax8.png" docs/images/default_rsaa.png
bash tools/crops.sh "$out/compare/default" 100x75+250+40 docs/images/default_crops_star.png
bash tools/crops.sh "$out/compare/default" 100x75+331+172 docs/images/default_crops_box.png
diagnosis_steps
step "bench, RSAA against its baselines" bench-rsaa.md
$rsaa bench --techniques "fxaa,msaa 4x,rsaa 4x gl4x sadp auth0,rsaa 4x gl4x sadp-plane auth1 cap1.5 mb sc fc me fe,rsaa 8x sadp auth0,rsaa 8x sadp-plane auth0,rsaa 8x sadp-plane auth1 cap1.5 mb sc fc me fe" \
  --frames 2 --orbit-frames 2 --out-dir "$out/bench-rsaa" >"$out/bench-rsaa.md"
goals_steps
cost_steps
papers_figures
coverage_steps
mkdir -p "$out/scene-tables"
for scene in builtin:default "$engine"; do
  name=$(basename "${scene#builtin:}"); name=${name%.*}
  step "scene-specific table, $name" "scene-table-$name.md"
  $rsaa train --from-scene "$scene" --out-dir "$out/scene-tables" >"$out/scene-table-$name.md" 2>&1
done
step "reliability report" docs/reliability.md
bash tools/reliability.sh
echo "all README figures done in $((SECONDS - started)) s" >&2
