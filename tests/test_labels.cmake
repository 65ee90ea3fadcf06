# The labels of fdh_tests' tests beyond `unit`, by test name (Suite.Test, whatever file or folder
# holds it). ctest reads this after the tests are discovered (tests/CMakeLists.txt), with their
# names in fdh_tests_TESTS; a name that no longer exists labels nothing. The labels are those of
# docs/building.md, "Tests by label":
#   whole-job  runs a whole fdhcert job (certify, report, fuzz, a scene run) through the program
#   slow       over about 20 s in a Release build
#   timed      gives a child a fixed wall time (10 s to make progress before SIGKILL): too little
#              at a sanitizer's speed

set(fdh_whole_job_tests
  # the shipped scenes simulated whole, each audited
  Scenes.RobustKeepsTheAuditAtZeroOnEveryShippedScene
  # report and fuzz killed and resumed again and again
  Kills.ReportKilledAnywhereAndInItsChartsLeavesWholeOutputs
  Kills.FuzzKilledAgainAndAgainAndResumedWithOtherOptionsEndsWithTheSameCases
  # whole certify runs with a one-thread plug-in
  Plugin.CertifyCatchesAPlugInThatBreaksItsPromise
  Plugin.CertifyCatchesALateTimeAndSavesTheCase)
set(fdh_slow_tests)
set(fdh_timed_tests
  Fuzz.KilledWithSigkillAndRestartedLosesNothing
  Fuzz.MovingRunKilledWithSigkillAndRestartedLosesNothing)

foreach(test IN LISTS fdh_tests_TESTS)
  set(labels)
  foreach(label whole-job slow timed)
    string(REPLACE "-" "_" list_name "fdh_${label}_tests")
    list(FIND ${list_name} "${test}" at)
    if(NOT at EQUAL -1)
      list(APPEND labels ${label})
    endif()
  endforeach()
  if(labels)
    set_tests_properties(${test} PROPERTIES LABELS "${labels}")
  endif()
endforeach()
