#!/bin/bash
# Issue 55, item 8 (in part): installing and citing.
#  - scripts/install-deps.sh --print, with every package reported missing (a
#    dpkg-query stand-in first on PATH), prints the apt-get line naming them,
#    exits 1 and calls neither apt-get nor sudo (stand-ins record any call);
#  - CITATION.cff states the version of CMakeLists.txt's project(VERSION) and a
#    date-released in YYYY-MM-DD form;
#  - CITATION.cff parses as YAML (a python3 with PyYAML, where there is one), its
#    top-level keys are keys of CFF 1.2.0, the required ones (cff-version,
#    message, title, authors) are there, and repository-code / repository / url,
#    where given, are http(s) URLs.
# Usage: install_cite.sh SOURCE_DIR WORK_DIR
set -u
src=$1 work=$2
rm -rf "$work" && mkdir -p "$work/shim" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
printf '#!/bin/sh\nexit 1\n' > "$work/shim/dpkg-query"
for c in apt-get sudo; do printf '#!/bin/sh\necho "%s $*" >> "%s/calls"\n' "$c" "$work" > "$work/shim/$c"; done
chmod +x "$work/shim/"*
PATH="$work/shim:$PATH" bash "$src/scripts/install-deps.sh" --print > "$work/out" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "install-deps --print with packages missing: exit $rc, expected 1"
grep -q '^  apt-get update && apt-get install -y --no-install-recommends cmake g++ make ' "$work/out" || fail "no apt-get line: $(cat "$work/out")"
[ -e "$work/calls" ] && fail "install-deps --print called: $(cat "$work/calls")"
v=$(sed -n 's/^project(drawbend VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
[ -n "$v" ] || fail "no project VERSION in CMakeLists.txt"
grep -q "^version: \"$v\"$" "$src/CITATION.cff" || fail "CITATION.cff: no version \"$v\""
grep -Eq '^date-released: "[0-9]{4}-[0-9]{2}-[0-9]{2}"$' "$src/CITATION.cff" || fail "CITATION.cff: no date-released"
cff_check='
import re, sys, yaml
d = yaml.safe_load(open(sys.argv[1]))
keys = {"abstract", "authors", "cff-version", "commit", "contact", "date-released", "doi", "identifiers", "keywords",
        "license", "license-url", "message", "preferred-citation", "references", "repository", "repository-artifact",
        "repository-code", "title", "type", "url", "version"}
bad = sorted(set(d) - keys)
miss = sorted({"cff-version", "message", "title", "authors"} - set(d))
urls = [k for k in ("repository-code", "repository", "repository-artifact", "url", "license-url")
        if k in d and not re.match(r"^https?://.+", str(d[k]))]
if bad or miss or urls or d["cff-version"] != "1.2.0":
    sys.exit("keys not in CFF 1.2.0: %s; missing: %s; not URLs: %s; cff-version %s" % (bad, miss, urls, d["cff-version"]))
'
yaml_py=""
for p in python3 /usr/bin/python3; do "$p" -c "import yaml" > /dev/null 2>&1 && { yaml_py=$p; break; }; done
if [ -n "$yaml_py" ]; then
  "$yaml_py" -c "$cff_check" "$src/CITATION.cff" || fail "CITATION.cff"
else
  echo "note: no python3 with PyYAML here: CITATION.cff's YAML not parsed"
fi
echo "install-deps prints 'apt-get install' without calling it; CITATION.cff version $v"
