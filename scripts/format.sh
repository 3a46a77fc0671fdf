#!/usr/bin/env bash
# Rewrites our C++ sources in place with the project's .clang-format.
set -euo pipefail
cd "$(dirname "$0")/.."
find Interfaces Physics Collision Framework ReferenceGame testbed tests bench packages \
  \( -name '*.h' -o -name '*.cpp' \) -not -path '*/fixtures/*' -not -path '*/course_host/framework/*' -print0 | xargs -0 -r clang-format -i
