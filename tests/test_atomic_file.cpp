// Bounded reads, all-or-nothing multi-file writes, the directory lock, and the names and
// positions that tables accept (issue 15). Core only: also run under the sanitizers.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "core/util/atomic_file.h"
#include "core/rsaa/offset_table.h"
#include "core/rsaa/sample_pattern.h"
#include "tests/test_util.h"

namespace rsaa {
namespace {

using test::TempDir;

std::size_t files_in(const std::string& dir) {
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) n += !e.is_directory();
  return n;
}

TEST(AtomicFiles, AFailingRenameMidwayRestoresThePreviousSet) {
  TempDir dir;
  test::write_text(dir.file("t.json"), "old json");
  test::write_text(dir.file("t.glsl"), "old glsl");
  // t.hlsl did not exist before: after the failure it must not exist either.
  int calls = 0;
  const RenameFn third_fails = [&](const std::string& from, const std::string& to, std::string& error) {
    if (++calls == 3) return error = "injected failure", false;
    return std::rename(from.c_str(), to.c_str()) == 0;
  };
  try {
    write_files_atomically({{dir.file("t.json"), "new json"}, {dir.file("t.glsl"), "new glsl"}, {dir.file("t.hlsl"), "new hlsl"}},
                           third_fails);
    FAIL() << "the failing rename was not reported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("t.hlsl"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("injected failure"), std::string::npos) << e.what();
  }
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(test::read_text(dir.file("t.json")), "old json");
  EXPECT_EQ(test::read_text(dir.file("t.glsl")), "old glsl");
  EXPECT_FALSE(std::filesystem::exists(dir.file("t.hlsl")));
  EXPECT_EQ(files_in(dir.path()), 2u) << "temporaries or backups left behind";
}

TEST(AtomicFiles, TemporariesOfDeadRunsAreRemovedOthersKept) {
  TempDir dir;
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);  // a PID that no longer runs
  const std::string pid = std::to_string(child);
  const std::string dead = dir.file(".t.rsaa-tmp-" + pid + "-0.json");
  const std::string live = dir.file(".t.rsaa-tmp-" + std::to_string(getppid()) + "-0.json");
  // A user's files that look like temporaries with a dead PID in them are not rsaa's: kept.
  const std::vector<std::string> unrelated = {dir.file("notes.tmp-1"), dir.file(".backup.tmp-" + pid + "-01.tar"),
                                              dir.file(".t.rsaa-tmp-" + pid + "-0x"), dir.file(".t.rsaa-tmp-" + pid)};
  for (const auto& p : {dead, live}) test::write_text(p, "x");
  for (const auto& p : unrelated) test::write_text(p, "x");
  write_file_atomically(dir.file("t.json"), "{}");
  EXPECT_FALSE(std::filesystem::exists(dead));
  EXPECT_TRUE(std::filesystem::exists(live));
  for (const auto& p : unrelated) EXPECT_TRUE(std::filesystem::exists(p)) << p;
  EXPECT_EQ(test::read_text(dir.file("t.json")), "{}");
}

// A target whose name is valid (up to 255 bytes) is written although ".NAME.rsaa-tmp-PID-N" would
// not be: the temporary's stem is shortened.
TEST(AtomicFiles, ATargetNameOfTheLongestLengthIsWritten) {
  TempDir dir;
  const std::string name = std::string(250, 'a') + ".json";
  ASSERT_EQ(name.size(), 255u);
  write_file_atomically(dir.file(name), "{}");
  EXPECT_EQ(test::read_text(dir.file(name)), "{}");
  EXPECT_EQ(files_in(dir.path()), 1u);
  EXPECT_LE(std::filesystem::path(temporary_path_beside(dir.file(name))).filename().string().size(), 255u);
}

// kill -9 among the renames: a child replaces the first file of three and dies (_exit, no
// unwinding); the set is mixed until the next write into the directory, which finishes the dead
// run's commit from its journal before its own, and leaves no temporary behind.
TEST(AtomicFiles, ARunKilledAmongItsRenamesIsFinishedByTheNext) {
  TempDir dir;
  for (const char* ext : {"json", "glsl", "hlsl"}) test::write_text(dir.file(std::string("t.") + ext), "old");
  const pid_t child = fork();
  if (child == 0) {
    int calls = 0;
    const RenameFn dies_at_the_second = [&](const std::string& from, const std::string& to, std::string&) {
      if (++calls == 2) _exit(9);
      return std::rename(from.c_str(), to.c_str()) == 0;
    };
    write_files_atomically({{dir.file("t.json"), "new json"}, {dir.file("t.glsl"), "new glsl"}, {dir.file("t.hlsl"), "new hlsl"}},
                           dies_at_the_second);
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 9) << "the child did not die among its renames";
  EXPECT_EQ(test::read_text(dir.file("t.json")), "new json");  // mixed, for now
  EXPECT_EQ(test::read_text(dir.file("t.glsl")), "old");
  EXPECT_GT(files_in(dir.path()), 3u) << "the dead run's temporaries and journal";

  write_file_atomically(dir.file("other.txt"), "x");  // any later write into the directory
  EXPECT_EQ(test::read_text(dir.file("t.json")), "new json");
  EXPECT_EQ(test::read_text(dir.file("t.glsl")), "new glsl");
  EXPECT_EQ(test::read_text(dir.file("t.hlsl")), "new hlsl");
  EXPECT_EQ(files_in(dir.path()), 4u) << "temporaries, backups or the journal left behind";
}

// A reader between the renames of a killed writer: with nothing written since, it reads the set
// as the dead run's journal finishes it (never old and new files mixed), for a kill at the first
// rename (nothing replaced yet) and at the second (the JSON replaced).
TEST(AtomicFiles, AReaderBetweenTheRenamesOfAKilledRunReadsOneSet) {
  for (int dies_at : {1, 2, 3}) {
    TempDir dir;
    OffsetTable old_table = fallback_table(builtin_pattern("d3d4x")), new_table = old_table;
    new_table.offsets[5] = {0.25, -0.5};
    write_offset_table_files(old_table, dir.path());
    const pid_t child = fork();
    if (child == 0) {
      int calls = 0;
      const RenameFn dies = [&](const std::string& from, const std::string& to, std::string&) {
        if (++calls == dies_at) _exit(9);
        return std::rename(from.c_str(), to.c_str()) == 0;
      };
      const std::string base = dir.file("d3d4x");
      write_files_atomically({{base + ".json", offset_table_json(new_table)},
                              {base + ".glsl", offset_table_glsl(new_table)},
                              {base + ".hlsl", offset_table_hlsl(new_table)}},
                             dies);
      _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 9) << "the child did not die among its renames";
    // On disk the set is mixed (after the first rename) or old; read, it is the new one.
    const OffsetTable read = read_offset_table(dir.file("d3d4x.json"));
    EXPECT_EQ(read.offsets[5], new_table.offsets[5]) << "killed at rename " << dies_at;
    EXPECT_EQ(read_committed_file(dir.file("d3d4x.glsl")), offset_table_glsl(new_table));
    EXPECT_EQ(read_committed_file(dir.file("d3d4x.hlsl")), offset_table_hlsl(new_table));
    // Reading wrote nothing: the dead run's temporaries and journal are still there.
    EXPECT_GT(files_in(dir.path()), 3u);
  }
}

// A journal whose temporary is elsewhere (not one a writer makes) is not followed.
TEST(AtomicFiles, AJournalPointingOutsideTheDirectoryIsNotFollowed) {
  TempDir dir, elsewhere;
  test::write_text(dir.file("t.json"), "target");
  test::write_text(elsewhere.file("x"), "elsewhere");
  const auto field = [](const std::string& s) { return std::to_string(s.size()) + ":" + s; };
  test::write_text(dir.file(".rsaa-commit.rsaa-tmp-1-0.journal"), field(elsewhere.file("x")) + field(dir.file("t.json")));
  EXPECT_EQ(read_committed_file(dir.file("t.json")), "target");
}

// A dead run's journal is a file anyone who can write the directory can make: the next writer
// there finishes only renames its run can have meant (a temporary of that run beside its target,
// both in the journal's directory). Followed blindly, it moved a file from anywhere and
// overwrote another (an absolute or a relative path, or a user's own file in the directory).
TEST(AtomicFiles, AJournalIsFollowedOnlyForItsRunsOwnTemporariesInItsDirectory) {
  TempDir dir, elsewhere;
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);  // a PID that no longer runs
  const std::string pid = std::to_string(child);
  const auto field = [](const std::string& s) { return std::to_string(s.size()) + ":" + s; };
  test::write_text(elsewhere.file("victim"), "user data");
  test::write_text(dir.file("payload"), "payload");
  test::write_text(dir.file("mine.txt"), "user file");
  const std::string journal = dir.file(".rsaa-commit.rsaa-tmp-" + pid + "-0.journal");
  for (const std::string& text : {
           field(elsewhere.file("victim")) + field(dir.file("moved")),              // a file from elsewhere
           field(dir.file("payload")) + field(elsewhere.file("victim")),            // over a file elsewhere
           field("payload") + field("mine.txt"),                                     // relative paths
           field(dir.file("payload")) + field(dir.file("mine.txt")),                // not a temporary
           field(dir.file(".payload.rsaa-tmp-1-0")) + field(dir.file("mine.txt")),  // another run's
       }) {
    SCOPED_TRACE(text);
    test::write_text(journal, text);
    write_file_atomically(dir.file("other.txt"), "x");  // any later write into the directory
    EXPECT_EQ(test::read_text(elsewhere.file("victim")), "user data");
    EXPECT_EQ(test::read_text(dir.file("payload")), "payload");
    EXPECT_EQ(test::read_text(dir.file("mine.txt")), "user file");
    EXPECT_FALSE(std::filesystem::exists(dir.file("moved")));
    EXPECT_TRUE(std::filesystem::exists(journal)) << "left for a person to look at";
  }
  // The run's own temporary beside its target is still finished.
  const std::string temporary = dir.file(".mine.rsaa-tmp-" + pid + "-1.txt");
  test::write_text(temporary, "committed");
  test::write_text(journal, field(temporary) + field(dir.file("mine.txt")));
  write_file_atomically(dir.file("other.txt"), "y");
  EXPECT_EQ(test::read_text(dir.file("mine.txt")), "committed");
  EXPECT_FALSE(std::filesystem::exists(journal));
}

// One set, one directory: the journal lists renames within it only.
TEST(AtomicFiles, ASetSpanningTwoDirectoriesIsRefused) {
  TempDir a, b;
  EXPECT_THROW(write_files_atomically({{a.file("x"), "1"}, {b.file("y"), "2"}}), std::logic_error);
  EXPECT_FALSE(std::filesystem::exists(a.file("x")));
  EXPECT_FALSE(std::filesystem::exists(b.file("y")));
}

TEST(AtomicFiles, ATargetThatIsNotAFileIsRefusedBeforeAnythingChanges) {
  TempDir dir;
  test::write_text(dir.file("t.json"), "old");
  std::filesystem::create_directories(dir.file("t.glsl/inside"));
  EXPECT_THROW(write_files_atomically({{dir.file("t.json"), "new"}, {dir.file("t.glsl"), "new"}}), std::runtime_error);
  EXPECT_EQ(test::read_text(dir.file("t.json")), "old");
  EXPECT_EQ(files_in(dir.path()), 1u);
}

TEST(BoundedReads, RefuseFifosDevicesDirectoriesAndOversizedFiles) {
  TempDir dir;
  ASSERT_EQ(mkfifo(dir.file("fifo").c_str(), 0600), 0);
  const auto message = [](const std::string& path, std::uint64_t limit) {
    try {
      read_whole_file(path, limit, "table");
    } catch (const LimitError& e) {
      return std::string(e.what());
    }
    return std::string("not refused");
  };
  EXPECT_NE(message(dir.file("fifo"), 1000).find("is a FIFO"), std::string::npos);  // returns at once
  EXPECT_NE(message("/dev/zero", 1000).find("/dev/zero: table is a character device"), std::string::npos);
  EXPECT_NE(message(dir.path(), 1000).find("is a directory"), std::string::npos);
  test::write_text(dir.file("big"), std::string(1001, 'x'));
  EXPECT_EQ(message(dir.file("big"), 1000), dir.file("big") + ": table is 1001 bytes; the limit is 1000 bytes");
  EXPECT_EQ(read_whole_file(dir.file("big"), 1001).size(), 1001u);
  EXPECT_THROW(read_whole_file(dir.file("missing")), std::runtime_error);
}

TEST(DirectoryLock, ASecondHolderIsRefusedUntilTheFirstLetsGo) {
  TempDir dir;
  {
    const DirectoryLock first(dir.path(), "rsaa train");
    try {
      const DirectoryLock second(dir.path(), "rsaa train");
      FAIL() << "two holders";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(dir.path() + ": another process holds this directory for rsaa train"),
                std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(DirectoryLock(dir.path(), "rsaa train"));
}

TEST(TableNames, OnlyLettersDigitsDashAndUnderscore) {
  EXPECT_TRUE(is_valid_pattern_name("custom-my_pattern2"));
  for (const std::string& bad : std::vector<std::string>{"", "custom-../x", "custom-a/b", "custom-a\nb", "custom-a b", "custom-\xc3\xa9",
                                std::string(65, 'a')})
    EXPECT_FALSE(is_valid_pattern_name(bad)) << bad;
  EXPECT_FALSE(is_known_pattern_name("custom-../../x"));
  EXPECT_FALSE(is_known_pattern_name("custom-"));
  EXPECT_THROW(pattern_from_positions("custom-a\n#error", {{0.25, 0.25}}), std::invalid_argument);

  TempDir dir;
  const OffsetTable table = fallback_table(builtin_pattern("d3d4x"));
  EXPECT_THROW(write_offset_table_files(table, dir.path(), "../escaped"), std::invalid_argument);
  EXPECT_THROW(write_offset_table_files(table, dir.path(), "a\nb"), std::invalid_argument);
  EXPECT_EQ(files_in(dir.path()), 0u);
}

TEST(TableNames, TheTrainingCommandCannotAddLinesToShaderCode) {
  OffsetTable table = fallback_table(builtin_pattern("d3d4x"));
  table.training["command"] = "rsaa train --from-scene 'a\n#error injected\r'";
  for (const std::string& text : {offset_table_glsl(table), offset_table_hlsl(table)}) {
    EXPECT_EQ(text.find("\n#error"), std::string::npos);
    EXPECT_NE(text.find("a\\x0a#error injected\\x0d"), std::string::npos);
  }
}

TEST(TableFiles, NonFiniteOrOutOfRangeOffsetsAreNeverWritten) {
  TempDir dir;
  OffsetTable table = fallback_table(builtin_pattern("d3d4x"));
  table.offsets[3].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(write_offset_table_files(table, dir.path()), std::invalid_argument);
  table.offsets[3].x = 1.5;
  EXPECT_THROW(write_offset_table_files(table, dir.path()), std::invalid_argument);
  EXPECT_EQ(files_in(dir.path()), 0u);
}

TEST(SamplePatterns, DegeneratePositionsAreRefused) {
  const double subnormal = std::numeric_limits<double>::denorm_min();
  EXPECT_THROW(pattern_from_positions("custom-s", {{subnormal, 0.25}, {0.25, -0.25}}), std::invalid_argument);
  EXPECT_THROW(pattern_from_positions("custom-s", {{1e-300, 0.25}}), std::invalid_argument);
  EXPECT_THROW(pattern_from_positions("custom-c", {{0.25, 0.25}, {0.25, 0.25 + 1e-9}}), std::invalid_argument);
  EXPECT_NO_THROW(pattern_from_positions("custom-ok", {{0.0, 0.25}, {0.25, 0.0}, {-0.5, 0.5}}));
  // The reader refuses them too, naming the file.
  const OffsetTable ok = fallback_table(pattern_from_positions("custom-s", {{0.125, 0.25}, {0.25, -0.25}}));
  std::string text = offset_table_json(ok);
  text.replace(text.find("[0.125, 0.25]"), 13, "[5e-324, 0.25]");
  try {
    parse_offset_table(text, "sub.json");
    FAIL() << "a subnormal sample position was accepted";
  } catch (const TableError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("sub.json: samples: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace rsaa
