#!/bin/bash
# The wide cross-check: every scene of Debian's povray-examples package rendered
# small by POV-Ray and by drt, compared after 4x4 downsampling (mean absolute
# sRGB difference, drt_wide_compare), and tabulated in docs/pov-crosscheck.md.
#
#   tests/pov_crosscheck/wide.sh [-b BUILD_DIR] [-j JOBS] reference [PATTERN..]
#                                                                          POV-Ray's renders (cached; all
#                                                                          scenes, or those matching)
#   tests/pov_crosscheck/wide.sh [-b BUILD_DIR] [-j JOBS] drt [PATTERN..]  drt's renders and figures
#                                                                          (all scenes, or those whose
#                                                                          path contains a PATTERN)
#   tests/pov_crosscheck/wide.sh table                                    the table in the docs (a scene
#                                                                          without a figure in the cache
#                                                                          keeps its row from the docs,
#                                                                          counted as carried over)
#   tests/pov_crosscheck/wide.sh [-b BUILD_DIR] [-j JOBS]                 all three
#
# POV-Ray's renders depend only on POV-Ray and the scenes, so they are kept in
# a cache folder outside the repository ($DRT_WIDE_CACHE, default
# ~/.cache/drt-pov-wide) and made once; drt's renders and figures are kept
# there too, so after a fix only the scenes it concerns need rendering again.
# Both renderers run on their own copy of the examples folder (some scenes
# write files), one thread each, under a CPU-time limit ($DRT_WIDE_CPU_LIMIT
# seconds, default 300).
#
# $DRT_WIDE_DRT picks another drt binary (default BUILD_DIR/drt) and
# $DRT_WIDE_RUN the cache sub-folder of its renders (default "drt"), e.g. to keep
# the figures of an older drt beside the current ones.
#
# Settings: 160x120; POV-Ray `+A0.3` (its adaptive anti-aliasing); drt 16
# samples per pixel, seed 1. Animated scenes render their first frame in both:
# clock = 0, or, when a same-named .ini beside the scene sets an animation
# (Final_Frame above Initial_Frame), that .ini's first frame and clock range
# (the portfolio scenes index their arrays by frame_number). Needs Debian's
# povray, povray-examples, povray-includes.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$root/build
jobs=1
while getopts b:j: option; do
    case $option in
    b) build=$option; build=$OPTARG ;;
    j) jobs=$OPTARG ;;
    *) sed -n '2,12p' "$0" >&2; exit 2 ;;
    esac
done
shift $((OPTIND - 1))
case $build in /*) ;; *) build=$root/$build ;; esac

examples=/usr/share/doc/povray/examples
cache=${DRT_WIDE_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/drt-pov-wide}
cpu_limit=${DRT_WIDE_CPU_LIMIT:-300}
width=160 height=120 spp=16 threshold=0.05
doc=$root/docs/pov-crosscheck.md
causes=$root/tests/pov_crosscheck/wide-causes.txt
drtbin=${DRT_WIDE_DRT:-$build/drt}
run=${DRT_WIDE_RUN:-drt}
export cache cpu_limit width height spp build examples drtbin run

all_scenes() { (cd "$examples" && find . -name '*.pov' | sed 's|^\./||' | LC_ALL=C sort); }

# A private copy of the examples folder for each renderer.
tree() {
    if [ ! -d "$cache/tree-$1" ]; then
        mkdir -p "$cache" && cp -r "$examples" "$cache/tree-$1.tmp" && mv "$cache/tree-$1.tmp" "$cache/tree-$1"
    fi
}

# The animation a same-named .ini beside the scene sets, as "FIRST LAST CLOCK0 CLOCK1"
# (nothing when there is no such .ini or it sets no more than one frame).
ini_frames() {
    local ini=$examples/${1%.pov}.ini first last clock0 clock1
    [ -f "$ini" ] || return 0
    value() { grep -i -m 1 "^[[:space:]]*$1[[:space:]]*=" "$ini" | cut -d = -f 2 | tr -dc '0-9.-'; }
    first=$(value Initial_Frame) last=$(value Final_Frame) clock0=$(value Initial_Clock) clock1=$(value Final_Clock)
    first=${first:-1} last=${last:-$first}
    [ "$last" -gt "$first" ] 2>/dev/null || return 0
    echo "$first $last ${clock0:-0} ${clock1:-1}"
}

# POV-Ray's render of one scene: $cache/pov/SCENE.png, or SCENE.failed with the reason.
reference_one() {
    scene=$1
    out=$cache/pov/${scene%.pov}
    [ -f "$out.png" ] || [ -f "$out.failed" ] && return 0
    mkdir -p "$(dirname "$out")"
    dir=$cache/tree-pov/$(dirname "$scene")
    file=$(basename "$scene")
    image=wide-${file%.pov}.png
    local animation=()
    read -r first last clock0 clock1 < <(ini_frames "$scene")
    [ -n "${first:-}" ] && animation=("+KFI$first" "+KFF$last" "+KI$clock0" "+KF$clock1" "+SF$first" "+EF$first")
    start=$(date +%s)
    (cd "$dir" && ulimit -t "$cpu_limit" &&
        exec povray "+I$file" "+O$image" "+W$width" "+H$height" -D +A0.3 +FN +WT1 "${animation[@]}" >"$out.log" 2>&1)
    status=$?
    seconds=$(($(date +%s) - start))
    # an animation's frame carries its number before the extension
    [ -n "${first:-}" ] && for framed in "$dir/${image%.png}"[0-9]*.png; do [ -f "$framed" ] && mv "$framed" "$dir/$image"; done
    if [ $status -eq 0 ] && [ -f "$dir/$image" ]; then
        mv "$dir/$image" "$out.png"
    elif [ $status -eq 152 ] || [ $status -eq 137 ]; then
        echo "POV-Ray exceeded ${cpu_limit} s of CPU" >"$out.failed"
    else
        reason=$(grep -m 1 -E 'Parse Error|Error:|error' "$out.log" | cut -c 1-120)
        echo "POV-Ray failed (status $status): ${reason:-see the log}" >"$out.failed"
    fi
    rm -f "$dir/$image"
    echo "pov  $scene ${seconds}s $(cat "$out.failed" 2>/dev/null)"
}

# drt's render of one scene and its figure: $cache/drt/SCENE.result holds
# "STATUS<TAB>MAE<TAB>SECONDS<TAB>DETAIL" (STATUS: compared, drt-failed, no-reference,
# both-failed: POV-Ray fails on the scene as well).
drt_one() {
    scene=$1
    out=$cache/$run/${scene%.pov}
    ref=$cache/pov/${scene%.pov}
    mkdir -p "$(dirname "$out")"
    dir=$cache/tree-drt/$(dirname "$scene")
    file=$(basename "$scene")
    rm -f "$out.png" "$out.result"
    local animation=()
    read -r first last clock0 clock1 < <(ini_frames "$scene")
    [ -n "${first:-}" ] && animation=(--frames "$first..$last" --clock "$clock0..$clock1" --subset "$first..$first")
    start=$(date +%s)
    (cd "$dir" && ulimit -t "$cpu_limit" &&
        exec "$drtbin" render "$file" -o "$out.png" --width "$width" --height "$height" --spp "$spp" \
            --threads 1 --seed 1 --quiet "${animation[@]}" >"$out.log" 2>&1)
    status=$?
    [ -n "${first:-}" ] && [ ! -f "$out.png" ] && for framed in "$out"[0-9]*.png; do [ -f "$framed" ] && mv "$framed" "$out.png"; done
    seconds=$(($(date +%s) - start))
    if [ $status -ne 0 ] || [ ! -f "$out.png" ]; then
        if [ $status -eq 152 ] || [ $status -eq 137 ]; then
            detail="drt exceeded ${cpu_limit} s of CPU"
        else
            detail=$(grep -m 1 -E 'error' "$out.log" | sed 's/^[^ ]*: //' | cut -c 1-140)
        fi
        if [ -f "$ref.failed" ]; then # POV-Ray refuses the scene too: not drt's failure
            printf 'both-failed\t-\t%s\t%s\n' "$seconds" "drt: ${detail:-status $status}; $(cat "$ref.failed")" >"$out.result"
        else
            printf 'drt-failed\t-\t%s\t%s\n' "$seconds" "${detail:-status $status}" >"$out.result"
        fi
    elif [ ! -f "$ref.png" ]; then
        printf 'no-reference\t-\t%s\t%s\n' "$seconds" "$(cat "$ref.failed" 2>/dev/null)" >"$out.result"
    else
        mae=$("$build/tests/drt_wide_compare" "$out.png" "$ref.png" "$out-diff.png")
        printf 'compared\t%s\t%s\t\n' "${mae:-9}" "$seconds" >"$out.result"
    fi
    echo "drt  $scene ${seconds}s $(cut -f 1,2,4 "$out.result" | tr '\t' ' ')"
}
export -f ini_frames reference_one drt_one

# The scenes whose path contains one of the patterns (all scenes without any).
matching_scenes() {
    if [ $# -eq 0 ]; then
        all_scenes
    else
        for pattern in "$@"; do all_scenes | grep -F -- "$pattern"; done | LC_ALL=C sort -u
    fi
}

reference() {
    command -v povray >/dev/null || { echo "wide.sh: povray is not installed" >&2; exit 1; }
    [ -d "$examples" ] || { echo "wide.sh: $examples is missing (povray-examples)" >&2; exit 1; }
    tree pov
    matching_scenes "$@" | xargs -P "$jobs" -I{} bash -c 'reference_one "$1"' _ {}
}

drt_renders() {
    [ -n "${DRT_WIDE_DRT:-}" ] || cmake --build "$build" --target drt >/dev/null || exit 1
    cmake --build "$build" --target drt_wide_compare >/dev/null || exit 1
    tree drt
    matching_scenes "$@" | xargs -P "$jobs" -I{} bash -c 'drt_one "$1"' _ {}
}

# A scene's flags for the summary: needs animation (clock), radiosity, photons.
flags() {
    local text
    text=$(grep -v '^[[:space:]]*//' "$examples/$1")
    echo "$text" | grep -qw clock && printf 'clock '
    echo "$text" | grep -qw radiosity && printf 'radiosity '
    echo "$text" | grep -qw photons && printf 'photons '
}

# The unsupported-feature warnings drt gave, shortened and joined.
warnings_of() {
    grep -E 'not supported|approximated|ignored' "$cache/$run/${1%.pov}.log" 2>/dev/null |
        sed -E 's/^[^:]*:[0-9]+:[0-9]+: warning: //; s/ is not supported( and is ignored)?//' |
        LC_ALL=C sort -u | head -n 3 | paste -sd ';' | sed 's/;/; /g' | cut -c 1-160
}

table() {
    local rows="" fresh="" total=0 agree=0 compared=0 drt_failed=0 no_ref=0 both_failed=0 missing=0 carried=0
    local clock=0 radiosity=0 photons=0
    while read -r scene; do
        total=$((total + 1))
        result=$cache/$run/${scene%.pov}.result
        cause=$(grep -F -m 1 "$scene	" "$causes" 2>/dev/null | cut -f 2)
        f=$(flags "$scene")
        old_row=""
        if [ ! -f "$result" ]; then
            old_row=$(grep -F -m 1 "| $scene | " "$doc")
        fi
        if [ ! -f "$result" ] && [ -z "$old_row" ]; then
            missing=$((missing + 1))
            rows+="| $scene | - | not rendered | |"$'\n'
            continue
        fi
        if [ -n "$old_row" ]; then # not rendered in this cache: the row of the previous table
            carried=$((carried + 1))
            mae=$(echo "$old_row" | cut -d '|' -f 3 | tr -d ' ')
            detail=$(echo "$old_row" | cut -d '|' -f 5- | sed 's/^ //; s/ |$//')
            detail=${detail//\\|/|}
            case $(echo "$old_row" | cut -d '|' -f 4 | sed 's/^ //; s/ $//') in
            agrees | differs) status=compared ;;
            "drt fails") status=drt-failed ;;
            "both fail") status=both-failed ;;
            "no POV-Ray image") status=no-reference ;;
            *) status=missing ;;
            esac
            if [ $status = missing ]; then
                missing=$((missing + 1)) carried=$((carried - 1))
                rows+="| $scene | - | not rendered | |"$'\n'
                continue
            fi
            [ -n "$cause" ] || cause=${detail//|/\\|}
        else
            IFS=$'\t' read -r status mae _ detail <"$result"
            fresh+="${fresh:+, }${scene%.pov}"
        fi
        case $status in
        compared)
            compared=$((compared + 1))
            if awk "BEGIN { exit !($mae <= $threshold) }"; then
                agree=$((agree + 1))
                rows+="| $scene | $mae | agrees | |"$'\n'
                continue
            fi
            [ -n "$cause" ] || cause=$(warnings_of "$scene")
            rows+="| $scene | $mae | differs | ${cause:-not yet analysed} |"$'\n'
            ;;
        drt-failed)
            drt_failed=$((drt_failed + 1))
            rows+="| $scene | - | drt fails | ${cause:-${detail//|/\\|}} |"$'\n'
            ;;
        both-failed)
            both_failed=$((both_failed + 1))
            rows+="| $scene | - | both fail | ${detail//|/\\|} |"$'\n'
            ;;
        no-reference)
            no_ref=$((no_ref + 1))
            rows+="| $scene | - | no POV-Ray image | ${detail//|/\\|} |"$'\n'
            ;;
        esac
        case $f in *clock*) clock=$((clock + 1)) ;; esac
        case $f in *radiosity*) radiosity=$((radiosity + 1)) ;; esac
        case $f in *photons*) photons=$((photons + 1)) ;; esac
    done < <(all_scenes)
    local percent rendered rendered_percent
    percent=$(awk "BEGIN { printf \"%.1f\", 100 * $agree / $total }")
    rendered=$((total - no_ref - both_failed - missing))
    rendered_percent=$(awk "BEGIN { printf \"%.1f\", 100 * $agree / ($rendered > 0 ? $rendered : 1) }")
    {
        sed '/^<!-- wide:begin -->$/,$d' "$doc"
        echo '<!-- wide:begin -->'
        cat <<TEXT
## Every shipped scene

Every scene of Debian's \`povray-examples\` package ($(povray --version 2>&1 | grep -m 1 '^POV-Ray')) is rendered
at ${width}x${height} by POV-Ray (\`+A0.3\`) and by drt (\`drt render\`, ${spp} samples per pixel), each image is
box-filtered 4x4 in linear values and encoded to sRGB, and the figure is the mean absolute difference over the
pixels and the three channels (\`drt_wide_compare\`). A scene **agrees** when that figure is at most ${threshold}.
Animated scenes render their first frame in both: \`clock\` 0, or the first frame and clock of the animation that a
same-named \`.ini\` beside the scene sets (the portfolio scenes index their arrays by \`frame_number\`). Produced by

    tests/pov_crosscheck/wide.sh [-j JOBS]

(POV-Ray's images are cached outside the repository; after a change, \`wide.sh drt PATTERN\` renders again only the
scenes whose path contains PATTERN, and \`wide.sh table\` rewrites this section.)

**${agree} of ${total} scenes agree (${percent}%); of the ${rendered} scenes POV-Ray renders from the command line,
${agree} agree (${rendered_percent}%).** Of the others: $((compared - agree)) differ by more than
${threshold}, ${drt_failed} fail in drt, ${both_failed} fail in both (POV-Ray stops on them too), ${no_ref} have no POV-Ray image (POV-Ray failed or exceeded the
CPU limit of ${cpu_limit} s)$([ $missing -gt 0 ] && echo ", $missing were not rendered"). Among the scenes that do not agree,
${clock} use \`clock\` (animation), ${radiosity} radiosity and ${photons} photons.$([ $carried -gt 0 ] && echo "
$((total - carried)) rows come from this run's renders ($fresh); the other $carried are carried over from the
previous table (rendered by an earlier drt: run \`wide.sh\` in full to redo them).")

| scene | MAE | result | cause |
|---|---|---|---|
TEXT
        printf '%s' "$rows"
    } >"$doc.tmp" && mv "$doc.tmp" "$doc"
    echo "wide.sh: $agree of $total scenes agree ($percent%); wrote $doc"
}

case ${1:-all} in
reference) shift; reference "$@" ;;
drt) shift; drt_renders "$@" ;;
table) table ;;
all) reference && drt_renders && table ;;
*) sed -n '2,12p' "$0" >&2; exit 2 ;;
esac
