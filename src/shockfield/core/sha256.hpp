#pragma once
// SHA-256 (FIPS 180-4, "Secure Hash Standard", §6.2) of bytes in memory or of a file, as 64
// lowercase hex digits. Provenance records it for every potential, material and data file a run
// reads, so a run folder says exactly which file produced it.
#include <filesystem>
#include <string>
#include <string_view>

namespace shockfield {

std::string sha256_hex(std::string_view bytes);

/// Reads the file in blocks; an unreadable file is an InputError naming it.
std::string sha256_file_hex(const std::filesystem::path& file);

}  // namespace shockfield
