// Validators that check a command-line number as it was typed, before CLI11 converts it: CLI11
// 2.1 turns "-1" into 2^64-1 for an unsigned option, and its Range lets NaN through.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

namespace rsaa::cli {

// --threads beyond this is a typo, not a machine.
constexpr std::uint64_t kMaxThreads = 1024;

// Decimal digits only: no sign, exponent or hexadecimal, so nothing wraps around.
inline const CLI::Validator kWholeNumber(
    [](std::string& text) -> std::string {
      if (text.empty() || text.size() > 20) return "expected a whole number, got '" + text + "'";
      for (char c : text)
        if (!std::isdigit(static_cast<unsigned char>(c)))
          return "expected a whole number (digits only), got '" + text + "'";
      // CLI11 would clamp a larger one to the largest 64-bit value.
      if (text.size() == 20 && text > "18446744073709551615")
        return "'" + text + "' is larger than 18446744073709551615";
      return "";
    },
    "WHOLE NUMBER");

// A finite decimal number within [lo, hi].
inline CLI::Validator finite_range(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0') return "expected a number, got '" + text + "'";
        if (!std::isfinite(v) || v < lo || v > hi)
          return "'" + text + "' is not a finite number within [" + CLI::detail::to_string(lo) + ", " +
                 CLI::detail::to_string(hi) + "]";
        return "";
      },
      "FINITE in [" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) + "]");
}

// Whole numbers within [lo, hi]: digits checked first, then the range.
inline CLI::Validator whole_range(std::uint64_t lo, std::uint64_t hi) {
  return kWholeNumber & CLI::Range(lo, hi);
}

// --anisotropy of the commands that render scenes (Scene::texture_anisotropy).
inline CLI::Option* add_anisotropy_option(CLI::App* cmd, float& anisotropy) {
  return cmd
      ->add_option("--anisotropy", anisotropy,
                   "Texture filtering: at most this many trilinear probes along a texture footprint's "
                   "long axis (anisotropic filtering; 1 = trilinear only)")
      ->check(finite_range(1, 16))
      ->capture_default_str();
}

}  // namespace rsaa::cli
