#include "shockfield/io/vtk_zlib.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "shockfield/core/error.hpp"

namespace shockfield::io {

namespace {

void append_u64(std::string& out, std::uint64_t v) {
  char bytes[sizeof v];
  std::memcpy(bytes, &v, sizeof v);
  out.append(bytes, sizeof v);
}

std::uint64_t header_entry(const std::string& bytes) {
  if (bytes.size() == 8) {
    std::uint64_t v;
    std::memcpy(&v, bytes.data(), 8);
    return v;
  }
  std::uint32_t v;
  std::memcpy(&v, bytes.data(), 4);
  return v;
}

}  // namespace

std::string vtk_zlib_compress(const void* data, std::size_t size, std::size_t block_size) {
  const auto* bytes = static_cast<const Bytef*>(data);
  const std::size_t blocks = (size + block_size - 1) / block_size;
  std::vector<std::string> compressed(blocks);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t n = std::min(block_size, size - b * block_size);
    uLongf length = compressBound(static_cast<uLong>(n));
    compressed[b].resize(length);
    // Level 1 (Z_BEST_SPEED): the output is written every frame; higher levels cost 3-5x the
    // time for a few percent (bench/RESULTS.md, "## VTK output").
    if (compress2(reinterpret_cast<Bytef*>(compressed[b].data()), &length, bytes + b * block_size,
                  static_cast<uLong>(n), 1) != Z_OK)
      throw RunError(fmt::format("zlib could not compress a block of {} bytes", n));
    compressed[b].resize(length);
  }
  std::string out;
  append_u64(out, blocks);
  append_u64(out, block_size);
  append_u64(out, size % block_size);  // 0: the last block is full (or there is none)
  for (const std::string& c : compressed) append_u64(out, c.size());
  for (const std::string& c : compressed) out += c;
  return out;
}

std::string vtk_zlib_decompress(const std::function<std::string(std::size_t)>& take, std::size_t header_size,
                                const std::function<std::string(std::string)>& to_native, std::uint64_t expected_size,
                                const std::string& where) {
  const auto entry = [&](const char* what) {
    const std::string bytes = take(header_size);
    if (bytes.size() < header_size)
      throw InputError(fmt::format("{}: the compressed data ends in its header ({})", where, what));
    return header_entry(to_native(bytes));
  };
  const std::uint64_t blocks = entry("number of blocks"), block_size = entry("block size"),
                      last_size = entry("last block size");
  const std::uint64_t last = last_size == 0 ? block_size : last_size;
  if (blocks == 0 ? expected_size != 0
                  : (block_size == 0 || last > block_size || (blocks - 1) > expected_size / block_size ||
                     (blocks - 1) * block_size + last != expected_size))
    throw InputError(fmt::format("{}: the compression header says {} blocks of {} bytes (last {}); expected {} "
                                 "bytes of data",
                                 where, blocks, block_size, last_size, expected_size));
  std::vector<std::uint64_t> sizes(blocks);
  for (std::uint64_t& s : sizes) s = entry("compressed block size");
  std::string out;
  out.reserve(expected_size);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::string packed = take(sizes[b]);
    if (packed.size() < sizes[b])
      throw InputError(fmt::format("{}: compressed block {} of {} ends after {} of its {} bytes", where, b + 1,
                                   blocks, packed.size(), sizes[b]));
    const std::uint64_t want = b + 1 == blocks ? last : block_size;
    std::string plain(want, '\0');
    uLongf length = static_cast<uLongf>(want);
    if (uncompress(reinterpret_cast<Bytef*>(plain.data()), &length, reinterpret_cast<const Bytef*>(packed.data()),
                   static_cast<uLong>(packed.size())) != Z_OK ||
        length != want)
      throw InputError(fmt::format("{}: compressed block {} of {} is not valid zlib data of {} bytes", where, b + 1,
                                   blocks, want));
    out += plain;
  }
  return out;
}

}  // namespace shockfield::io
