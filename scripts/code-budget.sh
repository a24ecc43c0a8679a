#!/usr/bin/env bash
# The code budget (doc/design.md, "The code budget"): fails when the house
# grows past it.
#   - no file in source/ over 600 lines, no header in include/ over 400;
#   - no function over 120 lines (declare_parameters up to 150), measured by
#     Universal Ctags from the line of the function's name to its closing
#     brace, lambdas counted in the function that holds them;
#   - source/core/hr_problem.cc at most 350 lines, with no Utilities::MPI
#     call and no loop over rows (the orchestrator runs stages, it does not
#     compute);
#   - no string comparison of a Newton-step path or linear solver name
#     outside a parse_parameters function (they are enums once parsed).
# Over-budget items that predate the budget are listed, with their size on
# the day they were listed, in scripts/code-budget-allowances.txt. Such an
# item fails the check when it grows, when it shrinks without its allowance
# being lowered, and when it is back within the budget but still listed: the
# list only shrinks. `--update` lowers or removes allowances (never raises or
# adds one) and rewrites the file; without the file it lists every item over
# the budget (the first listing).
#   bash scripts/code-budget.sh [--update]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
allowances=scripts/code-budget-allowances.txt
update=false
[ "${1:-}" = --update ] && update=true

# The budget; the project's to adjust, in one commit that says why.
max_source_lines=600
max_header_lines=400
max_function_lines=120
max_declare_parameters_lines=150
max_orchestrator_lines=350
orchestrator=source/core/hr_problem.cc

if ! command -v ctags > /dev/null || ! ctags --version 2>/dev/null | grep -q Universal; then
  echo "code-budget: needs Universal Ctags (Debian package universal-ctags)" >&2
  exit 2
fi

# The sources: tracked and new files (every source file outside a git
# checkout).
sources() {
  if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    git ls-files --cached --others --exclude-standard 'source/*.cc' 'include/*.h'
  else
    find source include -name '*.cc' -o -name '*.h' | sort
  fi
}

measured=$(mktemp)
trap 'rm -f "$measured" "$measured.new"' EXIT

# One line per measured item: KEY VALUE LIMIT.
{
  for f in $(sources); do
    n=$(wc -l < "$f")
    limit=$max_source_lines
    case $f in
      include/*) limit=$max_header_lines ;;
      "$orchestrator") limit=$max_orchestrator_lines ;;
    esac
    echo "lines:$f $n $limit"
  done

  # Functions: name, first line, last line, scope. Lambdas (__anon...) are
  # part of their function; an anonymous namespace is written (anonymous).
  sources |
    xargs ctags -x --kinds-c++=f --fields=+ne \
      --_xformat='%F|%N|%n|%e|%{scope}' -o - 2> /dev/null |
    awk -F'|' -v fl="$max_function_lines" -v dl="$max_declare_parameters_lines" '
      $2 ~ /^__anon/ { next }
      {
        scope = $5
        gsub(/__anon[0-9a-f]+/, "(anonymous)", scope)
        sub(/^hrcontact(::)?/, "", scope)
        name = (scope == "" ? "" : scope "::") $2
        gsub(/ /, "", name)
        len = $4 - $3 + 1
        limit = ($2 == "declare_parameters") ? dl : fl
        key = "function:" $1 ":" name
        if (!(key in longest) || len > longest[key]) { longest[key] = len; lim[key] = limit }
      }
      END { for (k in longest) print k, longest[k], lim[k] }'

  # The orchestrator computes nothing itself.
  echo "mpi-calls:$orchestrator $(grep -c 'Utilities::MPI' "$orchestrator" || true) 0"
  echo "row-loops:$orchestrator $(grep -cE 'for \(.*rows' "$orchestrator" || true) 0"

  # Path and solver names compared as strings outside parse_parameters.
  for f in $(sources); do
    ranges=$(ctags -x --kinds-c++=f --fields=+ne --_xformat='%N %n %e' -o - "$f" 2> /dev/null |
      awk '$1 == "parse_parameters" { print $2, $3 }')
    n=$({ grep -nE '(==|!=) *"(null-space|condensed|automatic|cg-amg|umfpack|mumps|direct)"|(path|solver)[a-z_.]* *(==|!=) *"' "$f" || true; } |
      cut -d: -f1 |
      awk -v r="$ranges" 'BEGIN { n = split(r, a, /[ \n]/) }
        { inside = 0; for (i = 1; i < n; i += 2) if ($1 >= a[i] && $1 <= a[i + 1]) inside = 1
          if (!inside) c++ }
        END { print c + 0 }')
    [ "$n" -eq 0 ] || echo "name-compares:$f $n 0"
  done
} | sort > "$measured"

declare -A allowed
if [ -f "$allowances" ]; then
  while read -r key value; do
    [[ -z "$key" || "$key" == \#* ]] && continue
    allowed[$key]=$value
  done < "$allowances"
fi

status=0
over=0
declare -A seen
: > "$measured.new"
while read -r key value limit; do
  seen[$key]=1
  if [ "$value" -le "$limit" ]; then
    if [ -n "${allowed[$key]:-}" ]; then
      if $update; then
        echo "removed: $key is within the budget ($value <= $limit)"
      else
        echo "STALE: $key is within the budget ($value <= $limit): remove its allowance"
        status=1
      fi
    fi
    continue
  fi
  over=$((over + 1))
  a=${allowed[$key]:-}
  if [ -z "$a" ] && $update && [ ! -f "$allowances" ]; then
    echo "listed: $key $value (first listing)"
    echo "$key $value" >> "$measured.new"
  elif [ -z "$a" ]; then
    echo "OVER BUDGET: $key is $value (budget $limit)"
    status=1
  elif [ "$value" -gt "$a" ]; then
    echo "GREW: $key is $value, its allowance $a (budget $limit)"
    status=1
  elif [ "$value" -lt "$a" ]; then
    if $update; then
      echo "lowered: $key $a -> $value"
      echo "$key $value" >> "$measured.new"
    else
      echo "SHRANK: $key is $value, its allowance $a: lower it (--update)"
      status=1
    fi
  else
    echo "$key $value" >> "$measured.new"
  fi
done < "$measured"
for key in "${!allowed[@]}"; do
  if [ -z "${seen[$key]:-}" ]; then
    if $update; then
      echo "removed: $key no longer exists"
    else
      echo "STALE: $key no longer exists: remove its allowance"
      status=1
    fi
  fi
done

if $update; then
  {
    echo "# Over-budget items that predate the budget (scripts/code-budget.sh),"
    echo "# with the size each may not exceed. The list only shrinks."
    sort "$measured.new"
  } > "$allowances"
  echo "code-budget: $allowances rewritten ($(wc -l < "$measured.new") allowances)"
  exit 0
fi
if [ $status -eq 0 ]; then
  echo "code-budget: passed; $over item(s) over the budget, each within its allowance"
else
  echo "code-budget: FAILED (the budget is at the top of scripts/code-budget.sh)"
fi
exit $status
