# The labels of fdh_tests' tests: `unit`, or those given here by test name (Suite.Test, whatever file or folder
# holds it). ctest reads this after the tests are discovered (tests/CMakeLists.txt), with their
# names in fdh_tests_TESTS; a name that no longer exists labels nothing. A test named here has
# the labels it is given instead of `unit` (fast, in-process; docs/building.md, "Tests by label"):
#   whole-job  a whole fdhcert job through the program (scene runs, report and fuzz killed and
#              resumed, certify with a one-thread plug-in): minutes under the sanitizers, left
#              out there (.ci/run)
#   slow       over 20 s in a Release ctest -j2, as measured (on a shared, loaded 2-core machine)
#   timed      gives a child fuzzer a fixed 10 s to make progress before SIGKILL, and so fails at
#              ASan's speed (FuzzToi's kill holds there: it runs under the sanitizers)

set(fdh_whole_job_tests
  Scenes.RobustKeepsTheAuditAtZeroOnEveryShippedScene
  Kills.ReportKilledAnywhereAndInItsChartsLeavesWholeOutputs
  Kills.FuzzKilledAgainAndAgainAndResumedWithOtherOptionsEndsWithTheSameCases
  Plugin.CertifyCatchesAPlugInThatBreaksItsPromise
  Plugin.CertifyCatchesALateTimeAndSavesTheCase
  SlowPlugins.ATightInclusionLikePlugInIsCertifiedToTheEnd
  SlowPlugins.TheBudgetCoversTheStartUpProbe
  SlowPlugins.ATwoSecondPerCallPlugInIsProbedToTheEnd
  SlowPlugins.AFuzzRunCutShortByTheBudgetLetsAnotherFamilyUseTheOut
  SlowPlugins.CertifyRunsTheStagesAskedInTheirOrderAndClassifyTimesBoth
  SlowPlugins.ClassifyAsksATimeThatGivesTheVerdictOncePerQuery)
# Seconds measured in the whole suite's run, in that order (load average 10 to 25): 165, 146,
# 144, 76, 71, 43, 35, 31, 30, 28, 26, 26, 24, 22, 21; these 15 alone, again at -j2 (load about
# 10): 28, 56, 56, 20, 26, 10, 8, 10, 13, 7, 10, 6, 11, 4, 9.
set(fdh_slow_tests
  Scenes.RobustKeepsTheAuditAtZeroOnEveryShippedScene
  Plugin.CertifyCatchesALateTimeAndSavesTheCase
  Plugin.CertifyCatchesAPlugInThatBreaksItsPromise
  Catalogue/SecondProbeFullDisk.IsExit2NamingItAndKeepsThePreviousCharts/report
  Catalogue/OutputFaults.GivesItsStatusAndMessage/report_full_disk_keeps_the_old_report
  Kills.ReportKilledAnywhereAndInItsChartsLeavesWholeOutputs
  BvhProperties.TraversalContainsBruteForce
  KdopProperties.FloatFdhContainsExactFdh
  AuditCommand.TheShippedScenesSimulatedOutputIsClean
  Kills.FuzzKilledAgainAndAgainAndResumedWithOtherOptionsEndsWithTheSameCases
  KdopProperties.OverlapNeverSaysDisjointWhenExactOverlaps
  Certify.TheSameCertificateForAnyThreadCount
  AuditBruteForce.ViolationsEqualAllPairsOnFoldedSheets
  Kills.CertifyKilledAnywhereLeavesWholeOutputs
  AuditBruteForce.ViolationsEqualAllPairs
  Certify.CertifiesTheCommittedCorpusAndCountsEveryCheck
  SlowPlugins.ATwoSecondPerCallPlugInIsProbedToTheEnd)
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
  if(NOT labels)
    set(labels unit)
  endif()
  set_tests_properties(${test} PROPERTIES LABELS "${labels}")
endforeach()
