#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "common/core/progress.hpp"
#include "common/core/require.hpp"

namespace mpfd {
namespace {

using ::testing::HasSubstr;

TEST(Assert, NamesTheExpressionTheMessageAndTheFile) {
  try {
    const int cells = 0;
    MPFD_ASSERT(cells > 0, "grid must have cells");
    FAIL() << "no error";
  } catch (const InvariantError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cells > 0"));
    EXPECT_THAT(e.what(), HasSubstr("grid must have cells"));
    EXPECT_THAT(e.what(), HasSubstr("core_test.cpp"));
  }
}

TEST(ProgressLine, ReportsPercentAndEtaFromElapsedWallTime) {
  std::ostringstream out;
  const ProgressLine line(out, 2.0e-3, "fdm", true);
  // Half the simulated time in 10 s of wall time leaves 10 s.
  const std::string text = line.format(120, 1.0e-3, 10.0);
  EXPECT_THAT(text, HasSubstr("step 120"));
  EXPECT_THAT(text, HasSubstr("50.0 %"));
  EXPECT_THAT(text, HasSubstr("ETA 00:00:10"));
}

TEST(ProgressLine, WritesNothingWhenNotATerminal) {
  std::ostringstream out;
  {
    ProgressLine line(out, 1.0, "mpm");
    EXPECT_FALSE(line.enabled());
    line.update(1, 0.5);
    line.finish(2, 1.0);
  }
  EXPECT_TRUE(out.str().empty());
}

TEST(ProgressLine, FinishEndsTheLineAtOneHundredPercent) {
  std::ostringstream out;
  {
    ProgressLine line(out, 1.0, "mpm", true);
    line.update(1, 0.25);
    line.finish(4, 1.0);
  }
  EXPECT_THAT(out.str(), HasSubstr("100.0 %"));
  EXPECT_EQ(out.str().back(), '\n');
}

TEST(Logger, LineCarriesSeverityModuleAndText) {
  std::ostringstream captured;
  auto* old = std::cerr.rdbuf(captured.rdbuf());
  Logger("fdm.scheme").warn("density ", 1.5, " kg/m^3");
  std::cerr.rdbuf(old);
  EXPECT_THAT(captured.str(), HasSubstr("[warn] fdm.scheme: density 1.5 kg/m^3"));
  EXPECT_THAT(captured.str(), ::testing::MatchesRegex("^[0-9]{4}-[0-9]{2}-[0-9]{2}T.*Z .*\n$"));
}

}  // namespace
}  // namespace mpfd

namespace mpfd {
namespace {

TEST(Require, MessageNamesWhereWhatRuleAndValue) {
  try {
    require(0.9 > 1.0, "ideal_gas", "gamma", 0.9, "> 1");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "ideal_gas: gamma must be > 1, got 0.9");
  }
}

TEST(Require, NanAndInfinityAlwaysFail) {
  EXPECT_THROW(require(true, "jwl", "a", std::nan(""), "finite"), Error);
  EXPECT_THROW(require(true, "jwl", "a", 1.0 / 0.0, "finite"), Error);
  EXPECT_NO_THROW(require(true, "jwl", "a", 3.712e11, "> 0"));
}

TEST(NumberText, ShortestTextReadsBackExactlyAndNumberTextRounds) {
  EXPECT_EQ(shortest_text(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(std::stod(shortest_text(2.0 / 3.0)), 2.0 / 3.0);
  EXPECT_EQ(number_text(0.1 + 0.2, 4), "0.3");
  EXPECT_EQ(number_text(20.984e9, 4), "2.098e+10");
}

}  // namespace
}  // namespace mpfd
