#!/bin/sh
# docs/reference/settings.md holds `depthscope settings` verbatim, in a fenced block between
# its BEGIN and END marker lines; this fails when the page and the command disagree.
#   settings_reference.sh DEPTHSCOPE [PAGE]
set -u
bin="${1:?usage: settings_reference.sh DEPTHSCOPE [PAGE]}"
page="${2:-$(dirname "$0")/../../docs/reference/settings.md}"
fail() { echo "FAIL: $*"; exit 1; }
[ -f "$page" ] || fail "no page $page"
work=$(mktemp -d) || fail "mktemp"
trap 'rm -rf "$work"' EXIT
"$bin" settings > "$work/command" || fail "$bin settings exited $?"
# The block: the lines between the markers, without the fence lines around them.
awk '
    $0 == "<!-- BEGIN depthscope settings -->" { inside = 1; next }
    $0 == "<!-- END depthscope settings -->" { inside = 0; found = 1; next }
    inside && !/^```/ { print }
    END { if (!found) exit 1 }
' "$page" > "$work/page" ||
    fail "$page has no block between <!-- BEGIN depthscope settings --> and <!-- END depthscope settings -->"
if ! cmp -s "$work/page" "$work/command"; then
    echo "$page differs from \`depthscope settings\` (- page, + command):"
    diff -u "$work/page" "$work/command" | tail -n +3
    fail "the settings page is out of date: regenerate it with tools/settings-reference $bin"
fi
echo "ok: $page matches \`depthscope settings\` ($(wc -l < "$work/command") lines)"
