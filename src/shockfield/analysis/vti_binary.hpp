#pragma once
// Binary data arrays of VTK XML files (ParaView's default when saving image data: appended raw
// data), uncompressed: format="binary" (base64 inside the DataArray) and format="appended"
// (<AppendedData encoding="raw"> or "base64", the array at `offset` after the '_'). Each array is
// a header (the byte count, UInt32 or UInt64 as the VTKFile's header_type says; UInt32 if absent)
// followed by the values, in the VTKFile's byte_order. Header and data may be base64-encoded
// together or one after the other (both are in use). Files with compressor="vtkZLibDataCompressor"
// hold each array as zlib blocks (io/vtk_zlib); other compressors (LZ4, LZMA) are refused with a
// message saying how to save the file readable.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace shockfield::analysis {

/// Value of attribute `key` in an XML start tag (`<Name a="1" b="2"`); empty if absent.
std::string xml_attribute(std::string_view tag, const std::string& key);

/// The whole file as text; InputError "PATH: cannot open".
std::string read_whole_file(const std::string& path);

/// The file a parallel VTK file's (.pvti, .pvtp) <Piece Source="…"> names, next to or below it:
/// `extension` (".vti", ".vtp") and relative without "..", else InputError at `where`.
std::string piece_file(const std::string& parallel_file, const std::string& source, const std::string& extension,
                       const std::string& where);

struct VtiBinary {
  std::string_view text;  ///< the whole file
  std::string where;      ///< "file:line" of the DataArray, for messages
  std::string name;       ///< the DataArray's Name
  std::string type;       ///< its type: Int8 … UInt64, Float32, Float64

  /// format="binary": the base64 text starts at text[body]. Returns `count` values as doubles.
  std::vector<double> inline_values(std::size_t body, std::size_t count) const;
  /// format="appended": the array starts `offset` bytes (raw) or characters (base64) after the
  /// '_' that opens the appended data.
  std::vector<double> appended_values(double offset, std::size_t count) const;
};

}  // namespace shockfield::analysis
