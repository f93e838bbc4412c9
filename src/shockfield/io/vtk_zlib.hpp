#pragma once
// Compressed data arrays of VTK XML files in the layout of VTK's vtkZLibDataCompressor (what
// ParaView writes with "Compressor Type: ZLib"): the raw bytes are cut into blocks of
// `block_size` bytes (the last one may be shorter), each block is compressed with zlib
// (RFC 1950) on its own, and the array is stored as a header followed by the compressed blocks:
//   [number of blocks, uncompressed block size, uncompressed size of the last block (0 when it is
//    a full block), compressed size of block 1, …, compressed size of block n]
// each header entry a UInt32 or a UInt64 as the VTKFile's header_type says (shockfield writes
// UInt64). Reference: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
// ("Compressed Data").
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace shockfield::io {

/// Most bytes zlib's deflate can pack into one (its limit is 1032:1), which bounds the values a
/// compressed file of a given size can hold.
inline constexpr std::size_t kZlibMaxExpansion = 1032;

/// VTK's default block size (vtkDataCompressor: 32 KiB).
inline constexpr std::size_t kVtkZlibBlockSize = 32768;

/// Header and compressed blocks of `size` bytes, header entries UInt64 (little-endian host).
std::string vtk_zlib_compress(const void* data, std::size_t size, std::size_t block_size = kVtkZlibBlockSize);

/// The uncompressed bytes of one compressed array read through `take(n)` (the next n bytes of
/// the file; fewer at its end), with header entries of `header_size` bytes (4 or 8) already in
/// host order after `to_native`. `expected_size` is the byte count the array must decompress to.
/// `where` names the file and array in messages; every inconsistency is an InputError.
std::string vtk_zlib_decompress(const std::function<std::string(std::size_t)>& take, std::size_t header_size,
                                const std::function<std::string(std::string)>& to_native, std::uint64_t expected_size,
                                const std::string& where);

}  // namespace shockfield::io
