#include "pfx/host/import_result.hpp"

#include <utility>

namespace pfx::host {

ImportResult::ImportResult(const pfx_importer_desc& importer, const pfx_import_request& request)
    : importer_(&importer) {
  importer.import(&request, &result_);
}

ImportResult::~ImportResult() { reset(); }

ImportResult::ImportResult(ImportResult&& other) noexcept
    : importer_(other.importer_), result_(std::exchange(other.result_, nullptr)) {}

ImportResult& ImportResult::operator=(ImportResult&& other) noexcept {
  if (this != &other) {
    reset();
    importer_ = other.importer_;
    result_ = std::exchange(other.result_, nullptr);
  }
  return *this;
}

void ImportResult::reset() {
  if (result_) importer_->release(result_);
  result_ = nullptr;
}

}  // namespace pfx::host
