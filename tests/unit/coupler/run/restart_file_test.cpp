// The coupler's part of a coupled checkpoint (coupler/run/restart_file.hpp): a
// protocol feature the stopped run's solvers offered must be offered again, and a
// refusal names the file, the entry and what each side offered.
#include "coupler/run/restart_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "common/core/error.hpp"

namespace mpfd::coupler {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

TEST(RestartFile, A_feature_offered_then_must_be_offered_again) {
  const auto file = std::filesystem::temp_directory_path() / "mpfd-restart-file-feature.h5";
  {
    io::Hdf5File h5(file, io::Hdf5File::Mode::create);
    RestartWriter out(h5);
    out.feature("step", "fdm_outflow", true);
    out.feature("step", "mpm_outflow", false);
  }
  const io::Hdf5File h5(file, io::Hdf5File::Mode::read);
  const RestartReader in(h5);
  EXPECT_NO_THROW(in.expect_feature("step", "fdm_outflow", true));
  EXPECT_NO_THROW(in.expect_feature("step", "mpm_outflow", false));
  const auto refusal = [&](const char* name, bool offered) {
    try {
      in.expect_feature("step", name, offered);
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(refusal("fdm_outflow", false),
              AllOf(HasSubstr(file.string()), HasSubstr("used 'fdm_outflow' (/step/fdm_outflow)"),
                    HasSubstr("this one does not")));
  EXPECT_THAT(refusal("mpm_outflow", true),
              AllOf(HasSubstr("did not use 'mpm_outflow'"), HasSubstr("this one does:")));
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace mpfd::coupler
