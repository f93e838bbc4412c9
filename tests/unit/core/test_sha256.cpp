// SHA-256 against the FIPS 180-2 example vectors (NIST) and, at the padding boundaries (55, 56,
// 63, 64, 119, 120 bytes), against Python's hashlib (values printed by
// `python3 -c "import hashlib; print(hashlib.sha256(b'a'*55).hexdigest())"`). Digests are exact:
// one wrong bit anywhere changes every digit.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <fstream>

#include "shockfield/core/error.hpp"
#include "shockfield/core/sha256.hpp"

using namespace shockfield;

TEST(Sha256, NistVectors) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PaddingBoundariesMatchHashlib) {
  const std::vector<std::pair<std::size_t, std::string>> expected{
      {55, "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318"},
      {56, "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a"},
      {63, "7d3e74a05d7db15bce4ad9ec0658ea98e3f06eeecf16b4c6fff2da457ddc2f34"},
      {64, "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb"},
      {119, "31eba51c313a5c08226adf18d4a359cfdfd8d2e816b13f4af952f7ea6584dcfb"},
      {120, "2f3d335432c70b580af0e8e1b3674a7c020d683aa5f73aaaedfdc55af904c21c"}};
  for (const auto& [n, digest] : expected) EXPECT_EQ(sha256_hex(std::string(n, 'a')), digest) << n;
}

TEST(Sha256, FileDigestEqualsTheDigestOfItsBytes) {
  // 76800 bytes of every byte value: more than one 64 KiB read block, binary-safe (NUL, 0xff).
  std::string bytes;
  for (int k = 0; k < 300; ++k)
    for (int b = 0; b < 256; ++b) bytes.push_back(static_cast<char>(b));
  const auto path = shockfield::testing::scratch_path("shockfield_sha256.bin");
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_EQ(sha256_file_hex(path), "f8b0585eb91f58c007a5634362c9f90d8543822c113f702523bc7b73408a9392");
  EXPECT_EQ(sha256_file_hex(path), sha256_hex(bytes));
  std::filesystem::remove(path);
}

TEST(Sha256, UnreadableFileNamesTheFile) {
  const auto missing = shockfield::testing::scratch_path("shockfield_sha256_missing");
  try {
    sha256_file_hex(missing);
    FAIL() << "no error for a missing file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string() + ": cannot open"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sha256_file_hex(std::filesystem::temp_directory_path()), InputError);  // a folder
}
