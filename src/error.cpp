#include "geardyn/error.h"

namespace geardyn {
namespace {

std::string composeMessage(const std::string& key, const std::string& value,
                           const std::string& allowed) {
  std::string message = key;
  if (!value.empty()) {
    if (!key.empty()) message.append(" = ");
    message.append(value);
  }
  if (!message.empty()) message.append(": ");
  message.append(allowed);
  return message;
}

}  // namespace

InputError::InputError(std::string key, std::string value, std::string allowed)
    : std::invalid_argument(composeMessage(key, value, allowed)),
      key_(std::move(key)),
      value_(std::move(value)),
      allowed_(std::move(allowed)) {}

}  // namespace geardyn
