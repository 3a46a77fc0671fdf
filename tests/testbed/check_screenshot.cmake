# testbed.screenshot: runs the testbed headless on a virtual display (xvfb-run -a) for a few frames of the
# probe scene through a fixed camera, writes a PPM, and checks it with check_screenshot: the box's pixels
# have its colour and background pixels do not. Then checks that the checker fails on a wrong answer (the
# box said to be at its mirror image), so that a passing run means something.
# Run as: cmake -DXVFB_RUN= -DTESTBED= -DCHECKER= -DOUT= -DEYE= -DTARGET= -DFOV= -DCENTRE= -DHALF= -DCOLOUR=
#         -DBACKGROUND= -P check_screenshot.cmake
cmake_minimum_required(VERSION 3.20)
file(REMOVE ${OUT})
execute_process(
  COMMAND ${XVFB_RUN} -a -s "-screen 0 640x480x24" ${TESTBED} --scene probe --frames 5 --screenshot ${OUT}
          --size 320x240 --eye ${EYE} --target ${TARGET} --no-ui
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 40)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT})
  message(FATAL_ERROR "the testbed failed (${rc}):\n${out}${err}")
endif()
execute_process(COMMAND ${CHECKER} ${OUT} ${EYE} ${TARGET} ${FOV} ${CENTRE} ${HALF} ${COLOUR} ${BACKGROUND}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the screenshot does not show the box where the camera puts it")
endif()
string(REPLACE "," ";" c "${CENTRE}")
list(GET c 0 x)
list(GET c 1 y)
list(GET c 2 z)
execute_process(COMMAND ${CHECKER} ${OUT} ${EYE} ${TARGET} ${FOV} -${x},${y},${z} ${HALF} ${COLOUR} ${BACKGROUND}
  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "the checker passed a box at its mirror image (${rc}): it checks nothing")
endif()
