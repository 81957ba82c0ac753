// The forked child that runs Gmsh: its answer comes back, its own errors are thrown as they
// are, what it printed before it failed is shown, and a child that ends without answering is run
// again before the file is blamed.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "fe/GmshSandbox.hpp"
#include "signorini/core/Error.hpp"

namespace {

using signorini::InputError;
using signorini::detail::answerFromChild;
using signorini::detail::readAll;
using signorini::detail::writeAll;

// Counts the children started: each appends a line to `path`.
int linesIn(const std::string& path) {
  std::ifstream in(path);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

struct Attempts {
  std::string path = "/tmp/signorini-sandbox-test-" + std::to_string(::getpid());
  Attempts() { std::remove(path.c_str()); }
  ~Attempts() { std::remove(path.c_str()); }
  int record() const {  // in the child: the number of this attempt, from 1
    std::ofstream(path, std::ios::app) << "x\n";
    return linesIn(path);
  }
};

const auto receiveInt = [](int& into) { return [&into](int fd) { return readAll(fd, &into, sizeof into); }; };

TEST(GmshSandbox, AChildThatEndsWithoutAnswerIsRunAgain) {
  const Attempts attempts;
  int answer = 0;
  answerFromChild("test file", "testing", 30, [&](int fd) {
    if (attempts.record() == 1) _exit(1);  // the first child ends without a word
    const int value = 42;
    writeAll(fd, "A", 1);
    writeAll(fd, &value, sizeof value);
  }, receiveInt(answer));
  EXPECT_EQ(answer, 42);
  EXPECT_EQ(linesIn(attempts.path), 2);
}

// The InputError a child's work ends in, or "" if none.
template <class Work>
std::string inputErrorOf(const Work& work) {
  int answer = 0;
  try {
    answerFromChild("test file 'x.geo'", "testing", 30, work, receiveInt(answer));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GmshSandbox, AChildThatAlwaysFailsIsBlamedOnTheFileAfterThreeRuns) {
  const Attempts attempts;
  const std::string message = inputErrorOf([&](int) {
    attempts.record();
    std::fputs("Info    : reading\nFatal   : out of fuel\n", stderr);
    std::fflush(stderr);
    _exit(1);
  });
  EXPECT_NE(message.find("test file 'x.geo': Gmsh stopped with exit status 1 while testing (it printed: "
                         "Info    : reading Fatal   : out of fuel)"),
            std::string::npos)
      << message;
  EXPECT_EQ(linesIn(attempts.path), 3);
}

TEST(GmshSandbox, AnErrorTheChildReportsIsThrownAtOnce) {
  const Attempts attempts;
  const std::string message = inputErrorOf([&](int) {
    attempts.record();
    throw InputError("the file names no physical group");
  });
  EXPECT_EQ(message, "the file names no physical group");
  EXPECT_EQ(linesIn(attempts.path), 1);
}

}  // namespace
