// A test suite with one headless GL context for all its tests (made once per suite: llvmpipe
// contexts are slow to create).
#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "runtime/gl_context.h"

namespace rsaa::test {

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context() = std::make_unique<gl::HeadlessContext>(); }
  static void TearDownTestSuite() { context().reset(); }

 private:
  static std::unique_ptr<gl::HeadlessContext>& context() {
    static std::unique_ptr<gl::HeadlessContext> c;
    return c;
  }
};

}  // namespace rsaa::test
