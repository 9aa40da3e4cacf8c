// Provenance of a superelement from the files it was reduced from (provenance.hpp).
#include "seflex/io/provenance.hpp"

#include <ctime>

#include "seflex/io/sha256.hpp"

namespace seflex::io {

std::string iso_utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string model_source_hash(const fem::Model& model) {
  Sha256 h;
  for (const std::string& file : model.files) update_from_file(h, file, "cannot be read again to hash it");
  return h.hex_digest();
}

void record_source(se::Superelement& s, const fem::Model& model, const std::string& source_file,
                   const std::string& created) {
  s.source_file = source_file;
  s.source_hash = model_source_hash(model);
  s.created = created;
}

}  // namespace seflex::io
