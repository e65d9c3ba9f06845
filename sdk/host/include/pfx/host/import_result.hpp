// An importer's result, owned: the importer that made it releases it when the ImportResult goes
// (or at reset()), on every path out of the caller. Importers make no GL calls: any thread.
#pragma once

#include <pfx/pfx.h>

#include "pfx/host/api.hpp"

namespace pfx::host {

class PFX_HOST_API ImportResult {
 public:
  ImportResult() = default;
  // Runs importer.import(request) and keeps what it returned.
  ImportResult(const pfx_importer_desc& importer, const pfx_import_request& request);
  ~ImportResult();
  ImportResult(ImportResult&& other) noexcept;
  ImportResult& operator=(ImportResult&& other) noexcept;
  ImportResult(const ImportResult&) = delete;
  ImportResult& operator=(const ImportResult&) = delete;

  // The importer's result; null only when it could not allocate one (out of memory) or after
  // reset(). A failed import has a result too, with its status and error.
  const pfx_import_result* get() const { return result_; }
  const pfx_import_result* operator->() const { return result_; }
  const pfx_import_result& operator*() const { return *result_; }
  explicit operator bool() const { return result_ != nullptr; }
  // The result's status; PFX_OUT_OF_MEMORY without a result.
  pfx_status status() const { return result_ ? result_->status : PFX_OUT_OF_MEMORY; }
  bool ok() const { return status() == PFX_OK; }
  // The importer's message for a failed import; null when it gave none or there is no result.
  const char* error() const { return result_ ? result_->error : nullptr; }

  // Gives the result back to its importer now.
  void reset();

 private:
  const pfx_importer_desc* importer_ = nullptr;
  pfx_import_result* result_ = nullptr;
};

}  // namespace pfx::host
