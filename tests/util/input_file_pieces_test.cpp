// util/input_file's InputFilePieces: a file handed on in pieces of whole
// lines is the file (the pieces joined are its bytes), every piece but the
// last ends in '\n' and holds no more than the piece size unless one line is
// longer, rewind reads the same pieces again, and what readInputFile
// refuses it refuses with the same message, a file that grows past the
// limit while read included.
#include "util/input_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "testing/temp_folder.hpp"

namespace mpr {
namespace {
namespace fs = std::filesystem;

struct PiecesFolder : testing::TempFolder {
  PiecesFolder() : TempFolder("mpr-pieces") {}
};

void writeFile(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

std::vector<std::string> allPieces(InputFilePieces& f, std::size_t pieceBytes, const std::string& where) {
  std::vector<std::string> pieces;
  std::string_view piece;
  bool last = false;
  int lasts = 0;
  while (f.next(piece, last)) {
    EXPECT_EQ(lasts, 0) << where << ": a piece after the last";
    if (last) {
      ++lasts;
      EXPECT_EQ(piece.find('\n'), std::string_view::npos) << where << ": the last piece is what follows the last '\\n'";
    } else {
      EXPECT_FALSE(piece.empty()) << where;
      EXPECT_EQ(piece.back(), '\n') << where;
      // Longer than a piece only when it is one line.
      if (piece.size() > pieceBytes) {
        EXPECT_EQ(piece.find('\n'), piece.size() - 1) << where;
      }
    }
    pieces.emplace_back(piece);
  }
  EXPECT_EQ(lasts, 1) << where;
  return pieces;
}

std::string joined(const std::vector<std::string>& pieces) {
  std::string all;
  for (const std::string& p : pieces) all += p;
  return all;
}

TEST(InputFilePieces, ThePiecesAreTheFilesWholeLinesAndRewindReadsThemAgain) {
  PiecesFolder d;
  std::mt19937 rng(20261205);
  std::string longLine(10000, 'l');
  longLine.append("\nend");
  std::vector<std::string> texts = {"", "\n", "\n\n\n", "a", "a\nb", "a\nb\n", "x\r\n\r\n", longLine,
                                    std::string("nul\0inside\nand\0\n", 17)};
  for (int k = 0; k < 40; ++k) {  // random bytes, newlines dense or sparse
    std::string t(rng() % 3000, ' ');
    const unsigned every = 1 + rng() % 200;
    for (char& c : t) c = rng() % every == 0 ? '\n' : static_cast<char>(rng() % 256);
    texts.push_back(t);
  }
  int n = 0;
  for (const std::string& text : texts) {
    const fs::path p = d.path / std::to_string(n++);
    writeFile(p, text);
    for (std::size_t pieceBytes : {std::size_t{1}, std::size_t{3}, std::size_t{16}, std::size_t{61}, std::size_t{4096},
                                   InputFilePieces::kPieceBytes}) {
      const std::string where = p.string() + " in pieces of " + std::to_string(pieceBytes);
      InputFilePieces f(p.string(), 1 << 20, "the file", pieceBytes);
      const std::vector<std::string> first = allPieces(f, pieceBytes, where);
      ASSERT_EQ(joined(first), text) << where;
      std::string_view piece;
      bool last = false;
      EXPECT_FALSE(f.next(piece, last)) << where;
      f.rewind();
      EXPECT_EQ(allPieces(f, pieceBytes, where + ", rewound"), first) << where;
    }
  }
  // A file whose size stat does not give is read to its end.
  InputFilePieces status("/proc/self/status", 1 << 20, "the file", 64);
  const std::string read = joined(allPieces(status, 64, "/proc/self/status"));
  EXPECT_NE(read.find("VmRSS"), std::string::npos);
}

std::string messageOf(const auto& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(InputFilePieces, RefusesWhatReadInputFileRefusesWithItsMessage) {
  PiecesFolder d;
  writeFile(d.path / "big", std::string(100, 'x'));
  for (const std::string& path : {(d.path / "missing").string(), d.path.string(), std::string("/dev/zero"),
                                 (d.path / "big").string()}) {
    const std::string expected = messageOf([&] { readInputFile(path, 50, "the script"); });
    ASSERT_FALSE(expected.empty()) << path;
    EXPECT_EQ(messageOf([&] { InputFilePieces(path, 50, "the script"); }), expected) << path;
  }
}

TEST(InputFilePieces, AFileThatGrowsPastTheLimitWhileReadIsRefused) {
  PiecesFolder d;
  const fs::path p = d.path / "growing";
  std::string text;
  for (int i = 0; i < 8; ++i) text += "line " + std::to_string(i) + "\n";  // 56 bytes
  writeFile(p, text);
  InputFilePieces f(p.string(), 100, "the script", 16);
  std::string_view piece;
  bool last = false;
  ASSERT_TRUE(f.next(piece, last));
  EXPECT_FALSE(last);
  {
    std::ofstream more(p, std::ios::binary | std::ios::app);
    more << std::string(60, 'y') << "\n";
  }
  const std::string message = messageOf([&] {
    while (f.next(piece, last)) {
    }
  });
  EXPECT_EQ(message, "cannot read the script: it grew past the 100 bytes MPR reads");
}

}  // namespace
}  // namespace mpr
