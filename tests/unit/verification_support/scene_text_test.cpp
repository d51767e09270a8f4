#include "tests/verification/support/scene_text.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/core/error.hpp"

namespace mpfd::verification {
namespace {

using ::testing::HasSubstr;

TEST(SceneText, Replaced_changes_the_first_occurrence_only) {
  EXPECT_EQ(replaced("cells: [50, 50, 1]\ncells: [50]", "50", "100"),
            "cells: [100, 50, 1]\ncells: [50]");
}

TEST(SceneText, Replaced_all_changes_every_occurrence) {
  EXPECT_EQ(replaced_all("material: tnt\nmaterial: tnt\n", "tnt", "gas"),
            "material: gas\nmaterial: gas\n");
}

TEST(SceneText, A_missing_text_is_an_error_naming_it) {
  try {
    (void)replaced("method: afdmp", "method: cfdmp", "method: mpm");
    ADD_FAILURE() << "expected an error";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), HasSubstr("'method: cfdmp'"));
  }
  EXPECT_THROW((void)replaced_all("a", "b", "c"), Error);
  EXPECT_THROW((void)read_text("/nonexistent/scene.yaml"), Error);
}

}  // namespace
}  // namespace mpfd::verification
