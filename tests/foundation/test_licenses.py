# SPDX-License-Identifier: EPL-2.0
"""The licence contract: every component of every artifact REI ships is under a licence that
contract/licenses.json allows, or has a reasoned decision there; anything of the GPL family (GPL, LGPL, AGPL)
fails, naming the component and where it was found.

The components are found in the artifacts, never listed by hand:

* the shaded jars (the `<outputFile>` of every maven-shade-plugin in the root POM's modules, and the `rei`
  script's REI_JARS): each embedded `META-INF/maven/*/*/pom.xml` is a component, and every class or native
  library that is not REI's own is traced, by name and CRC, to the jar of the local Maven repository it was
  copied from, so a dependency whose jar carries no POM (Equinox, Guice, LSP4J, ...) is a component too; code
  that no jar there has fails;
* the Python package: `rei` and the distributions it needs at run time, transitively, with the extras the
  decisions name (importlib.metadata of the .venv running this test), and what their wheels bundle: nested
  distributions, the components of their CycloneDX SBOMs (PEP 770), the libraries auditwheel grafted in;
* the Eclipse p2 site: each bundle (Bundle-License, else its embedded POM, else the POM of the jar of the
  local Maven repository it is), and the jars nested in a bundle, as for the shaded jars;
* the VS Code extension: each package.json it packs (its own and node_modules/**), and its nested jars.

A licence is read from the POM's `<licenses>` (else the nearest parent POM's, from the local Maven
repository), else the jar's Bundle-License; from License-Expression, else License, else the classifiers of a
Python distribution; from `license` (or the legacy `licenses`) of a package.json. contract/licenses.json maps
the names found to SPDX ids, says which ids are allowed, and decides per component where the metadata is
missing or ambiguous.
"""

from __future__ import annotations

import fnmatch
import hashlib
import importlib.metadata
import io
import json
import re
import xml.etree.ElementTree as ET
import zipfile
from collections import Counter, defaultdict
from collections.abc import Iterator
from dataclasses import dataclass, replace
from functools import cache
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

REPO_ROOT = Path(__file__).resolve().parents[2]
DECISIONS = REPO_ROOT / "contract" / "licenses.json"
M2 = Path.home() / ".m2" / "repository"

MAVEN_BUILD = "mvn -B -s .mvn/settings.xml install -DskipTests"
SITE_BUILD = "scripts/build-eclipse.sh --skip-tests"
VSIX_BUILD = "scripts/build-vscode.sh"
PYTHON_ARTIFACT = "the Python package rei (.venv)"
#: REI's own code in its jars: under the project's licence (the root POM's <licenses>).
OWN_CODE = "org/rei/"
#: The entries of a jar that are code, so must belong to some component.
CODE = re.compile(r"\.(class|so|dll|dylib|jnilib)$")
GPL_NAME = re.compile(r"\b(A|L)?GPL|General Public Licen[cs]e|Affero", re.IGNORECASE)


# -- the decisions and SPDX ----------------------------------------------------------------------------------

@cache
def decisions() -> dict:
    return json.loads(DECISIONS.read_text(encoding="utf-8"))


def _normal(name: str) -> str:
    return " ".join(name.replace("\u00a0", " ").split()).strip(" .").lower()


def spdx_of(name: str) -> str:
    """The SPDX expression of a licence as the metadata writes it: an alias's, else the name itself."""
    aliases = {_normal(alias): spdx for alias, spdx in decisions()["aliases"].items()}
    return aliases.get(_normal(name), name.strip())


def alternatives(expression: str) -> list[list[str]]:
    """An SPDX expression as its OR-ed alternatives, each the ids that all apply (`X WITH Y` is one id)."""
    tokens = re.findall(r"\(|\)|[^\s()]+", expression)
    position = 0

    def peek() -> str:
        return tokens[position].upper() if position < len(tokens) else ""

    def parse_or() -> list[list[str]]:
        nonlocal position
        result = parse_and()
        while peek() == "OR":
            position += 1
            result = result + parse_and()
        return result

    def parse_and() -> list[list[str]]:
        nonlocal position
        result = parse_atom()
        while peek() == "AND":
            position += 1
            right = parse_atom()
            result = [left + other for left in result for other in right]
        return result

    def parse_atom() -> list[list[str]]:
        nonlocal position
        if peek() == "(":
            position += 1
            result = parse_or()
            position += 1  # ")"
            return result
        atom = tokens[position] if position < len(tokens) else ""
        position += 1
        if peek() == "WITH" and position + 1 < len(tokens):
            atom = f"{atom} WITH {tokens[position + 1]}"
            position += 2
        return [[atom]]

    result = parse_or()
    # Anything left over (a comma list, prose): the whole text as one unknown id, so it is never half-read.
    return result if position >= len(tokens) else [[expression.strip()]]


def allowed(spdx: str) -> bool:
    """An allowed id; `X WITH Y` and `X+` only add permissions to X, so they are allowed when X is."""
    base = spdx.split(" WITH ")[0].strip().removesuffix("+")
    known = {allowed_id.lower() for allowed_id in decisions()["allowed"]}
    return spdx.lower() in known or base.lower() in known


def gpl_family(spdx: str) -> bool:
    base = spdx.split(" WITH ")[0].strip()
    prefixes = tuple(decisions()["gpl_family"])
    return base.upper().startswith(prefixes) or bool(GPL_NAME.search(spdx))


def _fully_allowed(alternative: list[str]) -> bool:
    return all(allowed(spdx) for spdx in alternative)


# -- components ----------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Component:
    key: str                   # maven:GROUP:ARTIFACT, python:NAME, python:NAME!BUNDLED, npm:NAME, p2:BUNDLE
    version: str
    licenses: tuple[str, ...]  # as found; several = the metadata names several (an SPDX expression is one)
    source: str                # where the licence was read
    where: str                 # the artifact, and the entry inside it, the component was found in


def verdict(component: Component) -> str | None:
    """None when the component may be shipped, else the problem, naming the component and where it is."""
    found = f"{component.key} {component.version}".strip() + f" in {component.where}"
    offered = [alt for name in component.licenses for alt in alternatives(spdx_of(name))]
    entry = decisions()["components"].get(component.key)
    if entry is not None:
        status = entry.get("status", "decided")
        if status == "violation":
            return f"GPL-family: {found}: {entry['license']} - {entry['reason']}"
        if status == "runtime-library":  # the decisions' test keeps these to libraries in third-party wheels
            if offered != alternatives(entry["license"]):
                return (f"GPL-family: {found}: {' / '.join(component.licenses) or 'no licence'} (from "
                        f"{component.source}), not the {entry['license']} it was accepted under")
            return None
        decided = alternatives(entry["license"])
        offered_gpl = any(gpl_family(spdx) for alt in offered for spdx in alt)
        if offered_gpl and not any(sorted(alt) == sorted(choice) for alt in offered for choice in decided):
            return (f"GPL-family: {found}: the metadata says {' / '.join(component.licenses)} (from "
                    f"{component.source}), and the decision {entry['license']!r} is not one of its choices")
        return None
    if not component.licenses:
        return (f"no licence in the metadata of {found} (looked in {component.source}): decide on it in "
                "contract/licenses.json 'components', with its licence and the reason")
    several = len(component.licenses) > 1
    if (any(map(_fully_allowed, offered)) and not several) or all(map(_fully_allowed, offered)):
        return None
    gpl = [spdx for alt in offered for spdx in alt if gpl_family(spdx)]
    if gpl:
        advice = ("several licences are named: if it is offered under either, elect the allowed one in "
                  "contract/licenses.json 'components' with the reason; else replace it") if several else \
            "replace it, or record it in contract/licenses.json as a violation until it is replaced"
        return f"GPL-family: {found}: {' / '.join(component.licenses)} (from {component.source}): {advice}"
    unknown = sorted({spdx for alt in offered for spdx in alt if not allowed(spdx)})
    return (f"licence not allowed or not recognised: {found}: {', '.join(unknown)} (from "
            f"{component.source}): map the name to its SPDX id in contract/licenses.json 'aliases', "
            "allow the id with a reason, or decide on the component")


# -- Maven metadata ------------------------------------------------------------------------------------------

def _xml(text: bytes) -> ET.Element:
    root = ET.fromstring(text)
    for node in root.iter():
        if isinstance(node.tag, str) and "}" in node.tag:
            node.tag = node.tag.split("}", 1)[1]
    return root


def _m2_file(group: str, artifact: str, version: str, ext: str) -> Path:
    return M2.joinpath(*group.split("."), artifact, version, f"{artifact}-{version}.{ext}")


@cache
def _root_pom() -> ET.Element:
    return _xml((REPO_ROOT / "pom.xml").read_bytes())


def _pom_file(group: str, artifact: str, version: str) -> Path | None:
    root = _root_pom()
    if (root.findtext("groupId"), root.findtext("artifactId")) == (group, artifact):
        return REPO_ROOT / "pom.xml"  # REI's parent, installed in the local repository or not
    path = _m2_file(group, artifact, version, "pom")
    return path if path.is_file() else None


def pom_licenses(pom: ET.Element, source: str) -> tuple[tuple[str, ...], str]:
    """The licences a POM declares, else its nearest parent's, and where they were read."""
    for _ in range(20):
        names = tuple((license_.findtext("name") or license_.findtext("url") or "").strip()
                      for license_ in pom.findall("licenses/license"))
        if names:
            return names, source
        parent = pom.find("parent")
        if parent is None:
            return (), source
        coordinates = [parent.findtext(tag, "").strip() for tag in ("groupId", "artifactId", "version")]
        path = _pom_file(*coordinates)
        if path is None:
            return (), f"{source}, whose parent {':'.join(coordinates)} is not in {M2}"
        pom, source = _xml(path.read_bytes()), f"parent POM {':'.join(coordinates)}"
    return (), source


def bundle_licenses(manifest: str) -> tuple[str, ...]:
    """The licences of a MANIFEST.MF's Bundle-License header (SPDX ids or URLs, attributes dropped)."""
    match = re.search(r"^Bundle-License:\s*(.+)$", re.sub(r"\r?\n ", "", manifest), re.MULTILINE)
    if match is None:
        return ()
    clauses = re.findall(r'(?:"[^"]*"|[^,"])+', match[1].strip())
    return tuple(clause.split(";")[0].strip().strip('"') for clause in clauses if clause.strip())


def _manifest(jar: zipfile.ZipFile) -> str:
    try:
        return jar.read("META-INF/MANIFEST.MF").decode("utf-8", "replace")
    except KeyError:
        return ""


@dataclass(frozen=True)
class M2Index:
    by_entry: dict[tuple[str, int], list[Path]]
    by_jar: dict[Path, frozenset[tuple[str, int]]]
    by_artifact: dict[tuple[str, str], list[Path]]


@cache
def m2_index() -> M2Index:
    """Every code entry (name, CRC) of every jar in the local Maven repository, both ways."""
    if not M2.is_dir():
        pytest.fail(f"no local Maven repository at {M2}: run `{MAVEN_BUILD}` at the repository root, which "
                    "downloads the dependencies this test traces the shaded code to", pytrace=False)
    by_entry: dict[tuple[str, int], list[Path]] = defaultdict(list)
    by_jar: dict[Path, frozenset[tuple[str, int]]] = {}
    by_artifact: dict[tuple[str, str], list[Path]] = defaultdict(list)
    for path in M2.rglob("*.jar"):
        if path.name.endswith(("-sources.jar", "-javadoc.jar")):
            continue
        try:
            with zipfile.ZipFile(path) as jar:
                entries = frozenset((info.filename, info.CRC) for info in jar.infolist()
                                    if CODE.search(info.filename))
        except (zipfile.BadZipFile, OSError):
            continue
        by_jar[path] = entries
        by_artifact[_coordinates(path)[:2]].append(path)
        for entry in entries:
            by_entry[entry].append(path)
    return M2Index(by_entry, by_jar, by_artifact)


def _coordinates(jar: Path) -> tuple[str, str, str]:
    """group, artifact, version of a jar in the local Maven repository, from its path."""
    parts = jar.relative_to(M2).parts
    return ".".join(parts[:-3]), parts[-3], parts[-2]


def trace(code: set[tuple[str, int]], embedded: set[tuple[str, str, str]]) -> tuple[list[Path], set]:
    """The jars of the local Maven repository the code was copied from - for each embedded POM its artifact's
    jar (that version when it has the code, else the version sharing most), then the jar with most of the
    rest, and so on - and the code no jar has."""
    index = m2_index()
    left = set(code)
    chosen: list[Path] = []
    for group, artifact, version in sorted(embedded):
        candidates = [jar for jar in index.by_artifact.get((group, artifact), ()) if left & index.by_jar[jar]]
        if candidates:
            jar = max(candidates, key=lambda c: (_coordinates(c)[2] == version, len(left & index.by_jar[c])))
            chosen.append(jar)
            left -= index.by_jar[jar]
    while left:
        counts = Counter(jar for entry in left for jar in index.by_entry.get(entry, ()))
        if not counts:
            break
        jar = max(counts, key=lambda candidate: (counts[candidate], str(candidate)))
        chosen.append(jar)
        left -= index.by_jar[jar]
    return chosen, left


def _untraced(left: set[tuple[str, int]], where: str) -> list[str]:
    packages = Counter(name.rsplit("/", 1)[0] for name, _ in left)
    return [f"code of no known component: {count} files in {package}/ of {where}: no jar in {M2} has them "
            "byte for byte (a dependency the local repository lacks - run the Maven build - or copied code)"
            for package, count in sorted(packages.items())]


def maven_component(group: str, artifact: str, version: str, where: str, pom: bytes | None = None,
                    pom_source: str = "") -> Component:
    """A Maven artifact: the licences of its POM (the given one, else the local repository's) or its parents',
    else the Bundle-License of its jar in the local repository."""
    licenses: tuple[str, ...] = ()
    source = pom_source
    if pom is not None:
        licenses, source = pom_licenses(_xml(pom), pom_source)
    if not licenses and (path := _pom_file(group, artifact, version)) is not None:
        licenses, source = pom_licenses(_xml(path.read_bytes()), str(path))
    if not licenses and (jar := _m2_file(group, artifact, version, "jar")).is_file():
        with zipfile.ZipFile(jar) as opened:
            if licenses := bundle_licenses(_manifest(opened)):
                source = f"Bundle-License of {jar}"
    return Component(f"maven:{group}:{artifact}", version, licenses, source or "no POM", where)


def jar_components(jar: zipfile.ZipFile, where: str) -> tuple[list[Component], list[str]]:
    """The components of a (shaded) jar, and the problems of code no component accounts for."""
    names = set(jar.namelist())
    components: dict[str, Component] = {}
    embedded: set[tuple[str, str, str]] = set()
    for name in sorted(names):
        if re.fullmatch(r"META-INF/maven/[^/]+/[^/]+/pom\.properties", name):
            text = jar.read(name).decode("latin-1")
            properties = dict(re.findall(r"^(\w+)\s*=\s*(.*?)\s*$", text, re.MULTILINE))
            group, artifact, version = properties["groupId"], properties["artifactId"], properties["version"]
            pom_name = name.removesuffix("properties") + "xml"
            pom = jar.read(pom_name) if pom_name in names else None
            embedded.add((group, artifact, version))
            component = maven_component(group, artifact, version, where, pom, f"{where}!{pom_name}")
            components.setdefault(component.key, component)
    code = {(info.filename, info.CRC) for info in jar.infolist()
            if CODE.search(info.filename) and not info.filename.startswith(OWN_CODE)}
    traced, left = trace(code, embedded)
    for path in traced:
        origin = maven_component(*_coordinates(path), where)
        known = components.get(origin.key)
        if known is None:
            components[origin.key] = replace(origin, source=f"{origin.source} (its code, traced by CRC)")
        elif not known.licenses and origin.licenses:  # EMF's embedded POMs name no licence, its jars' POMs do
            components[origin.key] = replace(known, licenses=origin.licenses, source=(
                f"{origin.source}: the POM of the jar its code comes from ({known.source} names none)"))
    if any(name.startswith(OWN_CODE) for name in names):
        licenses, source = pom_licenses(_root_pom(), "pom.xml")
        components["rei"] = Component("rei", _root_pom().findtext("version", ""), licenses,
                                      f"{source} (REI's own code, {OWN_CODE})", where)
    return list(components.values()), _untraced(left, where)


#: Nested jars by their SHA-256: the same jar inside the p2 plug-in and the .vsix is read once.
_NESTED: dict[str, tuple[list[Component], list[str]]] = {}


def nested_jars(container: zipfile.ZipFile, where: str) -> tuple[list[Component], list[str]]:
    """The components of the jars inside a bundle or an extension, as for the shaded jars."""
    components: list[Component] = []
    problems: list[str] = []
    for name in container.namelist():
        if name.endswith(".jar"):
            data = container.read(name)
            digest = hashlib.sha256(data).hexdigest()
            if digest not in _NESTED:
                with zipfile.ZipFile(io.BytesIO(data)) as jar:
                    _NESTED[digest] = jar_components(jar, "{where}")
            found, untraced = _NESTED[digest]
            here = f"{where}!{name}"
            components += [replace(component, where=here, source=component.source.replace("{where}", here))
                           for component in found]
            problems += [problem.replace("{where}", here) for problem in untraced]
    return components, problems


# -- the artifacts -------------------------------------------------------------------------------------------

def shaded_jars() -> list[Path]:
    """The `<outputFile>` of each maven-shade-plugin execution in the root POM's modules; `rei`'s REI_JARS."""
    jars = set()
    for module in _root_pom().findall("modules/module"):
        folder = REPO_ROOT / (module.text or "").strip()
        pom = _xml((folder / "pom.xml").read_bytes())
        for plugin in pom.iter("plugin"):
            if plugin.findtext("artifactId") != "maven-shade-plugin" or plugin.find("executions") is None:
                continue
            output = plugin.findtext(".//configuration/outputFile")
            assert output, f"{folder.name}/pom.xml: a shaded jar without <outputFile>: name it to check it"
            jars.add(folder / output.replace("${project.build.directory}", "target"))
    script = (REPO_ROOT / "rei").read_text(encoding="utf-8")
    block = re.search(r"^REI_JARS=\((.*?)\)", script, re.DOTALL | re.MULTILINE)
    assert block is not None, "rei: no REI_JARS=( ... )"
    jars |= {REPO_ROOT / jar for jar in re.findall(r'"([^"]+)"', block[1])}
    return sorted(jars)


def built(pattern: str, command: str) -> Path:
    """The artifact (the newest, for a glob); a missing one fails with the command that builds it."""
    found = sorted(REPO_ROOT.glob(pattern), key=lambda path: path.stat().st_mtime)
    if not found:
        pytest.fail(f"{pattern} is missing: build it with `{command}` at the repository root", pytrace=False)
    return found[-1]


def python_components() -> Iterator[Component]:
    """rei and what it needs at run time, transitively (with the extras the decisions count), and what their
    wheels bundle."""
    extras = frozenset(decisions()["python"]["extras"])
    queue: list[tuple[str, frozenset[str], str]] = [("rei", extras, "")]
    seen: set[str] = set()
    while queue:
        name, wanted, via = queue.pop(0)
        if canonicalize_name(name) in seen:
            continue
        seen.add(canonicalize_name(name))
        try:
            dist = importlib.metadata.distribution(name)
        except importlib.metadata.PackageNotFoundError:
            pytest.fail(f"{name} (required by {via}) is not installed in .venv: ./rei installs rei's "
                        "dependencies", pytrace=False)
        for line in dist.requires or ():
            requirement = Requirement(line)
            marker = requirement.marker
            if marker is None or any(marker.evaluate({"extra": extra}) for extra in ("", *sorted(wanted))):
                queue.append((requirement.name, frozenset(requirement.extras), dist.metadata["Name"]))
        where = f".venv: {dist.metadata['Name']} {dist.version}" + (f", required by {via}" if via else "")
        yield python_component(dist, where)
        yield from bundled_in_wheel(dist, where)


def python_component(dist: importlib.metadata.Distribution, where: str, prefix: str = "python:") -> Component:
    metadata = dist.metadata
    key = f"{prefix}{canonicalize_name(metadata['Name'])}"
    if expression := metadata.get("License-Expression"):
        return Component(key, dist.version, (expression,), "License-Expression", where)
    first_line = (metadata.get("License") or "").strip().split("\n")[0].strip()
    if first_line and first_line.upper() not in {"UNKNOWN", "NONE"} and len(first_line) < 100:
        return Component(key, dist.version, (first_line,), "License (its first line)", where)
    classifiers = tuple(classifier.rsplit(" :: ", 1)[1] for classifier in metadata.get_all("Classifier") or ()
                        if classifier.startswith("License :: ") and classifier.count(" :: ") >= 2)
    return Component(key, dist.version, classifiers, "License classifiers", where)


def bundled_in_wheel(dist: importlib.metadata.Distribution, where: str) -> Iterator[Component]:
    """What a wheel carries of others': nested distributions, its SBOMs' components, grafted libraries."""
    own = canonicalize_name(dist.metadata["Name"])
    files = [str(file) for file in dist.files or ()]
    for file in files:
        if re.fullmatch(r".+/[^/]+\.dist-info/METADATA", file):  # not its own, at the top
            nested = importlib.metadata.PathDistribution(Path(dist.locate_file(file)).parent)
            yield python_component(nested, f"{where}: {file}", f"python:{own}!")
    for file in files:
        if re.search(r"\.dist-info/sboms/[^/]+\.json$", file):
            sbom = json.loads(Path(dist.locate_file(file)).read_text(encoding="utf-8"))
            for part in sbom.get("components", ()):
                if part.get("type") not in (None, "library", "framework", "application"):
                    continue
                licenses = tuple(item.get("expression") or (item.get("license") or {}).get("id")
                                 or (item.get("license") or {}).get("name", "")
                                 for item in part.get("licenses", ()))
                yield Component(f"python:{own}!{part['name']}", part.get("version", ""), licenses,
                                f"CycloneDX SBOM {file}", f"{where}: {file}")
    stanzas = _license_stanzas(dist)
    for file in files:
        if re.fullmatch(r"[^/]+\.libs/[^/]+", file):
            library = re.split(r"-[0-9a-f]{8}|\.so", file.split("/", 1)[1])[0]  # auditwheel's hashes dropped
            matching = [license_ for pattern, license_ in stanzas
                        if fnmatch.fnmatch(file, pattern) or fnmatch.fnmatch(file, f"{pattern}.*")]
            licenses = (" AND ".join(f"({license_})" for license_ in matching),) if matching else ()
            yield Component(f"python:{own}!{library}", "", licenses,
                            "its licence files' Files:/License: stanza" if licenses else
                            "no Files:/License: stanza in its licence files", f"{where}: {file}")


def _license_stanzas(dist: importlib.metadata.Distribution) -> list[tuple[str, str]]:
    """(Files: glob, License:) of the stanzas a wheel's licence files give its bundled libraries (numpy's)."""
    stanzas = []
    for file in dist.files or ():
        if "/licenses/" in str(file) or Path(str(file)).name.upper().startswith(("LICENSE", "COPYING")):
            path = Path(dist.locate_file(file))
            if path.is_file() and path.stat().st_size < 2_000_000:
                text = path.read_text(encoding="utf-8", errors="replace")
                stanza = r"^Files:\s*(\S+)\s*\n(?:(?!Files:)[^\n]*\n)*?License:\s*(.+?)\s*$"
                stanzas += re.findall(stanza, text, re.MULTILINE)
    return stanzas


def npm_licenses(package: dict) -> tuple[str, ...]:
    license_ = package.get("license")
    if isinstance(license_, dict):
        license_ = license_.get("type")
    if isinstance(license_, str):
        return (license_,)
    return tuple(item.get("type", "") if isinstance(item, dict) else str(item)
                 for item in package.get("licenses") or ())


def vsix_components(vsix_path: Path) -> tuple[list[Component], list[str]]:
    where = str(vsix_path.relative_to(REPO_ROOT))
    components: list[Component] = []
    with zipfile.ZipFile(vsix_path) as vsix:
        for name in vsix.namelist():
            if re.fullmatch(r"extension/(node_modules/(@[^/]+/)?[^/@]+/)*package\.json", name):
                package = json.loads(vsix.read(name))
                components.append(Component(f"npm:{package['name']}", package.get("version", ""),
                                            npm_licenses(package), f"{name}: license", f"{where}!{name}"))
        nested, problems = nested_jars(vsix, where)
    return components + nested, problems


def site_components(site_path: Path) -> tuple[list[Component], list[str]]:
    where = str(site_path.relative_to(REPO_ROOT))
    components: list[Component] = []
    problems: list[str] = []
    with zipfile.ZipFile(site_path) as site:
        for name in site.namelist():
            if not (name.startswith("plugins/") and name.endswith(".jar")):
                continue
            bundle_where = f"{where}!{name}"
            with zipfile.ZipFile(io.BytesIO(site.read(name))) as bundle:
                manifest = _manifest(bundle)
                symbolic = re.search(r"^Bundle-SymbolicName:\s*([^;\s]+)", manifest, re.MULTILINE)
                version = re.search(r"^Bundle-Version:\s*(\S+)", manifest, re.MULTILINE)
                licenses, source = bundle_licenses(manifest), "its Bundle-License"
                poms = [entry for entry in bundle.namelist()
                        if re.fullmatch(r"META-INF/maven/[^/]+/[^/]+/pom\.xml", entry)]
                if not licenses and len(poms) == 1:
                    licenses, source = pom_licenses(_xml(bundle.read(poms[0])), f"{bundle_where}!{poms[0]}")
                if not licenses:  # e.g. LSP4J: neither; the bundle is a jar of Maven Central, as is
                    code = {(info.filename, info.CRC) for info in bundle.infolist()
                            if CODE.search(info.filename)}
                    traced, left = trace(code, set())
                    if len(traced) == 1 and not left:
                        origin = maven_component(*_coordinates(traced[0]), bundle_where)
                        licenses = origin.licenses
                        source = f"{origin.source} (the jar of the local Maven repository whose code it is)"
                    else:
                        problems.append(f"{bundle_where}: no Bundle-License, no POM, and its code is not one "
                                        f"jar of the local Maven repository ({len(traced)} jars, {len(left)} "
                                        "files untraced)")
                key = f"p2:{symbolic[1] if symbolic else name}"
                version_text = version[1] if version else ""
                components.append(Component(key, version_text, licenses, source, bundle_where))
                nested, nested_problems = nested_jars(bundle, bundle_where)
                components += nested
                problems += nested_problems
    return components, problems


# -- the tests -----------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def inventory() -> dict[str, tuple[list[Component], list[str]]]:
    """Per shipped artifact: its components, and the problems of code no component accounts for."""
    result: dict[str, tuple[list[Component], list[str]]] = {}
    for jar_path in shaded_jars():
        relative = str(jar_path.relative_to(REPO_ROOT))
        with zipfile.ZipFile(built(relative, MAVEN_BUILD)) as jar:
            result[relative] = jar_components(jar, relative)
    result[PYTHON_ARTIFACT] = (list(python_components()), [])
    site = built("releng/org.rei.site/target/org.rei.site-*.zip", SITE_BUILD)
    result[str(site.relative_to(REPO_ROOT))] = site_components(site)
    vsix = built("editors/vscode/dist/rei-*.vsix", VSIX_BUILD)
    result[str(vsix.relative_to(REPO_ROOT))] = vsix_components(vsix)
    return result


def test_every_shipped_component_has_an_allowed_licence(inventory: dict) -> None:
    problems = [problem for components, untraced in inventory.values()
                for problem in [*untraced, *filter(None, map(verdict, components))]]
    assert not problems, "\n".join(["shipped components without an allowed licence:", *problems])


def test_the_artifacts_have_the_components_they_are_known_to_have(inventory: dict) -> None:
    """The scan itself: it finds REI's own code and what each kind of metadata names (a scan finding nothing
    would pass the test above)."""
    keys = {artifact: {component.key for component in components}
            for artifact, (components, _) in inventory.items()}
    assert {"rei", "maven:org.eclipse.xtext:org.eclipse.xtext", "maven:org.eclipse.platform:org.eclipse.osgi",
            "maven:org.eclipse.lsp4j:org.eclipse.lsp4j"} <= keys[
        "bundles/org.rei.dsl.ide/target/rei-language-server.jar"]
    assert {"rei", "maven:io.netty:netty-common"} <= keys["sut-kits/java/target/rei-sut-kit.jar"]
    assert {"rei", "maven:org.eclipse.xtext:org.eclipse.xtext", "maven:org.antlr:antlr-runtime",
            "maven:com.fasterxml.jackson.core:jackson-databind"} <= keys[
        "bundles/org.rei.dsl.edit/target/rei-room-editor.jar"]
    assert {"python:rei", "python:numpy", "python:autobahn", "python:txaio"} <= keys[PYTHON_ARTIFACT]
    site = next(artifact for artifact in keys if artifact.endswith(".zip"))
    assert {"p2:org.rei.eclipse", "p2:org.eclipse.lsp4j",
            "maven:org.eclipse.xtext:org.eclipse.xtext"} <= keys[site]
    vsix = next(artifact for artifact in keys if artifact.endswith(".vsix"))
    assert {"npm:rei", "npm:vscode-languageclient", "maven:org.eclipse.xtext:org.eclipse.xtext"} <= keys[vsix]
    # rooms from occupancy maps: the map reader's YAML parser ships inside the language server and the generator,
    # so in both editors too, under Apache-2.0 as its POM says
    for artifact in ("bundles/org.rei.dsl.ide/target/rei-language-server.jar",
                     "generators/org.rei.cli/target/rei-cli.jar", site, vsix):
        snakeyaml = [c for c in inventory[artifact][0] if c.key == "maven:org.yaml:snakeyaml"]
        assert snakeyaml, f"{artifact} has no SnakeYAML (the map reader needs it)"
        assert {spdx_of(name) for c in snakeyaml for name in c.licenses} == {"Apache-2.0"}, snakeyaml


def test_the_decisions_are_consistent() -> None:
    data = decisions()
    assert not [spdx for spdx in data["allowed"] if gpl_family(spdx)], "the GPL family is never allowed"
    assert all(data["allowed"].values()), "every allowed licence has its reason"
    for name, spdx in data["aliases"].items():
        assert gpl_family(name) == any(gpl_family(i) for alt in alternatives(spdx) for i in alt), \
            f"alias {name!r} -> {spdx!r} hides or invents a GPL-family licence"
    for key, entry in data["components"].items():
        assert entry.get("reason"), f"{key}: a decision needs its reason"
        status = entry.get("status", "decided")
        assert status in {"decided", "violation", "runtime-library"}, f"{key}: unknown status {status!r}"
        if status == "runtime-library":
            in_a_wheel = key.startswith("python:") and "!" in key
            assert in_a_wheel and entry["license"] in data["runtime_library_licenses"], (
                f"{key}: 'runtime-library' is only for a library inside a third-party wheel, under one of "
                "'runtime_library_licenses'; anywhere else a GPL-family component is a violation")
        elif status == "decided":
            assert any(map(_fully_allowed, alternatives(entry["license"]))), (
                f"{key}: {entry['license']} is not allowed; a shipped GPL-family component is recorded with "
                '"status": "violation", never decided away')


def test_every_decision_names_a_shipped_component(inventory: dict) -> None:
    keys = {component.key for components, _ in inventory.values() for component in components}
    stale = sorted(set(decisions()["components"]) - keys)
    assert not stale, f"contract/licenses.json decides on components nothing ships any more: {stale}"


def test_what_is_not_shipped_stays_outside_the_python_package(inventory: dict) -> None:
    """The WAMP router (Crossbar.io) is not shipped: scripts/setup-router.sh installs it from PyPI into its
    own venv and REI runs it as a separate process. That holds only while rei does not depend on it."""
    keys = {component.key for component in inventory[PYTHON_ARTIFACT][0]}
    for name in decisions()["not_shipped"]:
        assert f"python:{canonicalize_name(name)}" not in keys, f"rei depends on {name} now: it is shipped"
