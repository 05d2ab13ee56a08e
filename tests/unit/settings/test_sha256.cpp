// SHA-256 against FIPS 180-4's examples and a block-boundary case, and the version string.
#include <gtest/gtest.h>

#include <string>

#include "renderer/common/sha256.h"
#include "renderer/common/version.h"

namespace ds {
namespace {

TEST(Sha256, KnownDigests) {
    EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    EXPECT_EQ(sha256_hex("abc"),
              "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
              "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
              "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PiecesGiveTheWholeDigest) {
    const std::string text(200, 'x');
    Sha256 pieces;
    for (size_t at = 0; at < text.size(); at += 7)
        pieces.update(text.data() + at, std::min<size_t>(7, text.size() - at));
    EXPECT_EQ(to_hex(pieces.finish()), sha256_hex(text));
}

TEST(Version, IsSet) {
    EXPECT_NE(std::string(version()), "");
}

}  // namespace
}  // namespace ds
