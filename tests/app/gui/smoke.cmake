# ctest driver for sph-gui under Xvfb. Variables: XVFB_RUN, GUI, CHECK, OUT, MODE (smoke | keys | match), SPH.
#   smoke: the issue's command line, then the screenshot checks;
#   keys:  quick key taps through the key callback (--tap-keys) are all taken;
#   end:   Space at t_end replays and stops at t_end again;
#   match: the GUI records the t = 0 frame of sod, the headless program renders the same frame, and the
#          two PNGs are compared;
#   ab:    an A/B comparison on sod (alpha = 1 against alpha = 0) at t = 0.15 with the inspector open on
#          particle 410: the screenshot shows both runs and the inspector, the legend both L1 values,
#          and the inspector's numbers are the engine's (INSPECT_CHECK);
#   click: a click on a particle's dot opens the inspector on it;
#   state: a checkpoint of `sph run` loads with --load-state at its step and time; a CSV given instead exits 3.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${OUT})
  message("$ ${ARGV}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "exit code ${rc}")
  endif()
endfunction()

if(MODE STREQUAL "state")
  run(${CMAKE_COMMAND} -E env OMP_WAIT_POLICY=passive ${SPH} run sod --set scene.n_left=100 --until 0.05
      --checkpoint-every 0.05 --quiet --out ${OUT}/run)
  file(STRINGS ${OUT}/run/diagnostics.csv rows)
  list(GET rows -1 last)
  string(REGEX MATCH "^[0-9]+" step "${last}")
  execute_process(COMMAND ${XVFB_RUN} -a ${GUI} --scene sod --paused --load-state ${OUT}/run/checkpoint.sph
                  --quit-after-frames 40 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${OUT})
  message("${out}${err}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "last state: step ${step}, t = 0.05\n")
    message(FATAL_ERROR "expected the loaded checkpoint's step ${step} at t = 0.05")
  endif()
  execute_process(COMMAND ${XVFB_RUN} -a ${GUI} --scene sod --paused --load-state ${OUT}/run/diagnostics.csv
                  --quit-after-frames 5 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${OUT})
  message("${out}${err}")
  if(NOT rc EQUAL 3 OR NOT err MATCHES "diagnostics.csv: not a checkpoint")
    message(FATAL_ERROR "expected exit 3 naming the file that is not a checkpoint")
  endif()
elseif(MODE STREQUAL "smoke")
  run(${XVFB_RUN} -a ${GUI} --scene sod --screenshot ${OUT}/shot.png --quit-after-frames 90)
  run(${CHECK} screenshot ${OUT}/shot.png)
elseif(MODE STREQUAL "keys")
  # Ten taps on S between two frames give ten single steps (a once-per-frame poll saw at most one);
  # a tap on R later resets to step 0.
  execute_process(COMMAND ${XVFB_RUN} -a ${GUI} --scene sod --paused --tap-keys 5:SSSSSSSSSS --quit-after-frames 60
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${OUT})
  message("${out}${err}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "last state: step 10,")
    message(FATAL_ERROR "expected 10 single steps from 10 quick taps on S")
  endif()
  execute_process(COMMAND ${XVFB_RUN} -a ${GUI} --scene sod --paused --tap-keys 5:SSSS --tap-keys 30:R
                  --quit-after-frames 60 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${OUT})
  message("${out}${err}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "last state: step 0,")
    message(FATAL_ERROR "expected a quick tap on R to reset to step 0")
  endif()
elseif(MODE STREQUAL "end")
  # Space at t_end with "stop at t_end" ticked replays from t = 0 and stops at t_end again (it ran on to
  # t = 0.77 on sod). t_end = 0.01 is reached long before the tap at frame 60.
  execute_process(COMMAND ${XVFB_RUN} -a ${GUI} --scene sod --set time.t_end=0.01 --tap-keys "60: "
                  --quit-after-frames 150 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${OUT})
  message("${out}${err}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "last state: step [0-9]+, t = 0.01\n")
    message(FATAL_ERROR "expected Space at t_end to replay and stop at t_end = 0.01")
  endif()
elseif(MODE STREQUAL "ab")
  execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x900x24" ${GUI} --scene sod --set time.t_end=0.15
                  --compare-set visc.alpha=0 --compare-set visc.beta=0 --inspect 410 --quit-at-end
                  --quit-after-frames 3000 --screenshot ${OUT}/ab.png
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${OUT})
  message("${out}${err}")
  file(WRITE ${OUT}/report.txt "${out}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "last state: step [0-9]+, t = 0.15\n")
    message(FATAL_ERROR "expected the run to stop at t_end = 0.15")
  endif()
  if(NOT out MATCHES "view legend: exact \\| A: visc.alpha=1, visc.beta=2 +L1_rho = [0-9.e-]+ \\| B: visc.alpha=0, visc.beta=0 +L1_rho = [0-9.e-]+")
    message(FATAL_ERROR "expected both runs with their L1 in the view's legend")
  endif()
  run(${CHECK} ab ${OUT}/ab.png)
  run(${INSPECT_CHECK} ${OUT}/report.txt sod 0.15)
elseif(MODE STREQUAL "click")
  # a click on particle 300's dot (through the view's picking) opens the inspector on it
  execute_process(COMMAND ${XVFB_RUN} -a ${GUI} --scene sod --paused --click-particle 20:300 --quit-after-frames 80
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${OUT})
  message("${out}${err}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "inspected particle 300 at step 0")
    message(FATAL_ERROR "expected a click on particle 300 to open the inspector on it")
  endif()
elseif(MODE STREQUAL "match")
  run(${XVFB_RUN} -a ${GUI} --scene sod --paused --record ${OUT}/gui --record-size 1280x720 --quit-after-frames 60)
  run(${SPH} run sod --until 0 --frames ${OUT}/headless --size 1280x720 --quiet)
  run(${CHECK} compare ${OUT}/gui/frame_00000.png ${OUT}/headless/frame_00000.png)
endif()
