#include "arg_reader.hpp"

namespace pfx::app {

bool ArgReader::value(std::string* into) {
  if (index_ + 1 >= args_.size()) return fail(arg() + " needs a value");
  *into = args_[++index_];
  return true;
}

bool ArgReader::value(std::vector<std::string>* list) {
  std::string text;
  if (!value(&text)) return false;
  list->push_back(text);
  return true;
}

bool ArgReader::fail(const std::string& message) {
  *error_ = message;
  return false;
}

}  // namespace pfx::app
