#include "coupler/run/restart_file.hpp"

#include <cmath>

#include "common/core/error.hpp"

namespace mpfd::coupler {

void RestartWriter::make_group(const std::string& owner) {
  if (!file_.exists("/" + owner)) file_.create_group("/" + owner);
}

void RestartWriter::number(const std::string& owner, const std::string& name, double value) {
  make_group(owner);
  file_.write_attribute("/" + owner, name, value);
}

void RestartWriter::optional_number(const std::string& owner, const std::string& name,
                                    std::optional<double> value) {
  number(owner, name, value.value_or(std::numeric_limits<double>::quiet_NaN()));
}

void RestartWriter::array(const std::string& owner, const std::string& name,
                          std::span<const double> values) {
  make_group(owner);
  file_.write_dataset("/" + owner + "/" + name, values, {values.size()}, "");
}

void RestartWriter::text(const std::string& owner, const std::string& name,
                         const std::string& value) {
  make_group(owner);
  file_.write_text("/" + owner + "/" + name, value);  // a dataset: records grow with the run
}

void RestartWriter::feature(const std::string& owner, const std::string& name, bool offered) {
  number(owner, name, offered ? 1 : 0);
}

void RestartReader::expect_feature(const std::string& owner, const std::string& name,
                                   bool offered) const {
  if ((number(owner, name) != 0) == offered) return;
  refuse("was written by a run that " + std::string(offered ? "did not use" : "used") + " '" +
         name + "' (/" + owner + "/" + name + "); this one " + (offered ? "does" : "does not") +
         ": restart with the solvers and the coupler of that run");
}

double RestartReader::number(const std::string& owner, const std::string& name) const {
  if (!file_.exists("/" + owner))
    refuse("has no group '/" + owner + "' (a coupler checkpoint has it)");
  try {
    return file_.read_attribute("/" + owner, name);
  } catch (const std::exception& error) {
    refuse("has no number '" + name + "' on '/" + owner + "': " + error.what());
  }
}

std::optional<double> RestartReader::optional_number(const std::string& owner,
                                                     const std::string& name) const {
  const double value = number(owner, name);
  return std::isnan(value) ? std::nullopt : std::optional<double>(value);
}

std::vector<double> RestartReader::array(const std::string& owner, const std::string& name,
                                         std::size_t count) const {
  const std::string path = "/" + owner + "/" + name;
  if (!file_.exists(path)) refuse("has no array '" + path + "' (a coupler checkpoint has it)");
  std::vector<double> values = file_.read_dataset(path).values;
  if (count != kAnyCount && values.size() != count)
    refuse("holds " + std::to_string(values.size()) + " values in '" + path +
           "'; this scene needs " + std::to_string(count));
  return values;
}

std::string RestartReader::text(const std::string& owner, const std::string& name) const {
  const std::string path = "/" + owner + "/" + name;
  if (!file_.exists(path)) refuse("has no text '" + path + "' (a coupler checkpoint has it)");
  return file_.read_text(path);
}

nlohmann::json RestartReader::json(const std::string& owner, const std::string& name) const {
  try {
    return nlohmann::json::parse(text(owner, name));
  } catch (const nlohmann::json::exception& error) {
    refuse("holds no JSON in '/" + owner + "/" + name + "': " + error.what());
  }
}

void RestartReader::refuse(const std::string& what) const {
  throw Error("restart: '" + file_.path().string() + "' " + what);
}

}  // namespace mpfd::coupler
