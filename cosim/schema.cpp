#include "cosim/schema.hpp"

#include <set>
#include <string>

#include "mpfd/cosim/v1/message.pb.h"
#include "mpfd/cosim/v1/recording.pb.h"

namespace mpfd::cosim {
namespace {

void add_with_dependencies(const google::protobuf::FileDescriptor* file,
                           std::set<std::string>& added, google::protobuf::FileDescriptorSet& set) {
  if (added.contains(file->name())) return;
  for (int i = 0; i < file->dependency_count(); ++i) {
    add_with_dependencies(file->dependency(i), added, set);
  }
  added.insert(file->name());
  file->CopyTo(set.add_file());
}

}  // namespace

google::protobuf::FileDescriptorSet schema_descriptor_set() {
  google::protobuf::FileDescriptorSet set;
  std::set<std::string> added;
  add_with_dependencies(v1::Header::descriptor()->file(), added, set);
  add_with_dependencies(v1::RecordHeader::descriptor()->file(), added, set);
  return set;
}

}  // namespace mpfd::cosim
