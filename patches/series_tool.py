#!/usr/bin/env python3
"""Builds the curated patch series described by patches/manifest.txt.

The manifest lists patches in order; each patch names the paths it brings from patches/BASE to
their state in a commit (HEAD by default). A path is claimed by the first patch whose pattern
matches it ("home" patch). A hunk rule moves the hunks of one file whose changed text matches a
regular expression to a LATER patch, so a file shared by several features (rendering_server.h,
light_storage.cpp, main.cpp ...) grows patch by patch. Hunks come from `git diff -U0 BASE TARGET`
and never overlap, so any subset of them applies to the BASE text; the state of a file after
patch k is BASE plus every hunk assigned to patches 1..k.

Commits are made with plumbing (a temporary index, fixed author and dates), so the same tree and
manifest always give byte-identical patches. Subcommands:
  write OUT_DIR [--target REV]   write OUT_DIR/<series>/NNNN-*.patch and OUT_DIR/INDEX
  check [--target REV]           every file under the covered roots is assigned; every quoted
                                 #include resolves after each patch; prints per-patch sizes
  plan  [--target REV]           prints, per patch, its files (and which are split by hunks)
  compare TREE [--target REV]    lists the carried paths where TREE (a tree or commit) differs from
                                 the target; exit status 1 when any does
Manifest syntax (one item a line; '#' starts a comment line):
  series NAME                    following patches belong to series NAME (a subfolder of OUT_DIR)
  patch SUBJECT                  starts a patch; SUBJECT is `Area: Summary`, at most 72 characters
  | TEXT                         one line of the patch's body (why); '|' alone is a blank line
  + GLOB                         paths this patch brings to the target state (fnmatch; ** spans /)
  ~ PATH REGEX                   hunks of PATH (claimed by an earlier patch) matching REGEX move here;
                                 rules are tried latest patch first, so a broad early rule (`area`) is
                                 the fallback of specific later ones (`area_shadow`)
  ~! PATH REGEX                  a pin: tried before every `~` rule (pins in manifest order), for a
                                 hunk that mixes features and is needed by the earliest of them; a pin
                                 in the file's home patch keeps the hunk there
  = OLD NEW                      NEW is OLD moved (git's rename detection adds its own pairs): NEW
                                 diffs against OLD's BASE text, and OLD is deleted in NEW's home patch
  exclude GLOB                   paths changed since BASE that no patch carries (results, binaries)
  cover ROOT                     roots the check covers (default: every changed path)
  generated GLOB                 generated data (the LUT): carried, but not counted in patch sizes
"""

import difflib
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
MANIFEST = os.path.join(ROOT, "patches", "manifest.txt")
AUTHOR = ("godot-area maintainers", "maintainers@godot-area.invalid", "1764633600 +0000")


def git(*args, input_bytes=None, env=None):
	result = subprocess.run(["git", "-C", ROOT] + list(args), input=input_bytes, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
	if result.returncode != 0:
		sys.exit("git %s failed: %s" % (" ".join(args), result.stderr.decode(errors="replace")))
	return result.stdout


class Patch:
	def __init__(self, series, subject, line):
		self.series = series
		self.subject = subject
		self.line = line
		self.body = []
		self.globs = []
		self.hunk_rules = []  # (path, compiled regex)
		self.files = []  # paths whose state changes in this patch


def glob_regex(pattern):
	# fnmatch, except that '*' stops at '/' and '**' spans folders.
	out = ""
	i = 0
	while i < len(pattern):
		if pattern.startswith("**", i):
			out += ".*"
			i += 2
		elif pattern[i] == "*":
			out += "[^/]*"
			i += 1
		elif pattern[i] == "?":
			out += "[^/]"
			i += 1
		else:
			out += re.escape(pattern[i])
			i += 1
	return re.compile(out + r"\Z")


def parse_manifest(path):
	patches = []
	excludes = []
	covers = []
	renames = []
	generated = []
	series = None
	errors = []
	with open(path, encoding="utf-8") as f:
		for number, raw in enumerate(f, 1):
			line = raw.rstrip("\n")
			where = "%s:%d" % (os.path.relpath(path, ROOT), number)
			if not line.strip() or line.startswith("#"):
				continue
			if line.startswith("series "):
				series = line[7:].strip()
			elif line.startswith("patch "):
				if series is None:
					errors.append(where + ": patch before any series line")
				subject = line[6:].strip()
				if len(subject) > 72:
					errors.append("%s: subject has %d characters (at most 72): %s" % (where, len(subject), subject))
				if not re.match(r"^[A-Za-z0-9_./+-]+: \S", subject):
					errors.append(where + ": subject is not `Area: Summary`: " + subject)
				patches.append(Patch(series, subject, where))
			elif line.startswith("|"):
				patches[-1].body.append(line[2:] if line.startswith("| ") else "")
			elif line.startswith("+ "):
				patches[-1].globs.append((line[2:].strip(), glob_regex(line[2:].strip())))
			elif line.startswith("~ ") or line.startswith("~! "):
				pin = line.startswith("~! ")
				parts = line[3 if pin else 2 :].strip().split(None, 1)
				if len(parts) != 2:
					errors.append(where + ": a hunk rule is `~ PATH REGEX`")
					continue
				patches[-1].hunk_rules.append((parts[0], re.compile(parts[1]), pin))
			elif line.startswith("= "):
				parts = line[2:].split()
				if len(parts) != 2:
					errors.append(where + ": a move is `= OLD NEW`")
					continue
				renames.append((parts[0], parts[1]))
			elif line.startswith("exclude "):
				excludes.append(glob_regex(line[8:].strip()))
			elif line.startswith("generated "):
				generated.append(glob_regex(line[10:].strip()))
			elif line.startswith("cover "):
				covers.append(line[6:].strip().rstrip("/"))
			else:
				errors.append(where + ": not understood: " + line)
	for p in patches:
		if not any(l.strip() for l in p.body):
			errors.append(p.line + ": patch has no body (say why): " + p.subject)
	return patches, excludes, covers, renames, generated, errors


def changed_paths(base, target):
	out = git("diff", "--no-renames", "--name-status", "-z", base, target).split(b"\0")
	paths = {}
	i = 0
	while i + 1 < len(out):
		status, path = out[i].decode(), out[i + 1].decode()
		paths[path] = status[0]
		i += 2
	return paths


def blob_ids(rev, paths):
	ids = {}
	out = git("ls-tree", "-r", "-z", "--full-tree", rev).split(b"\0")
	wanted = set(paths) if paths is not None else None
	for entry in out:
		if not entry:
			continue
		meta, path = entry.split(b"\t", 1)
		path = path.decode()
		if wanted is None or path in wanted:
			mode, kind, sha = meta.decode().split()
			ids[path] = (mode, sha)
	return ids


def read_blobs(shas):
	shas = sorted(set(shas))
	if not shas:
		return {}
	data = git("cat-file", "--batch", input_bytes=("\n".join(shas) + "\n").encode())
	blobs = {}
	pos = 0
	while pos < len(data):
		end = data.index(b"\n", pos)
		sha, kind, size = data[pos:end].decode().split()
		size = int(size)
		blobs[sha] = data[end + 1 : end + 1 + size]
		pos = end + 1 + size + 1
	return blobs


STRUCTURAL_LINES = {b"", b"}", b"};", b"{", b"return true;", b"return false;", b"return;", b"break;", b"} else {"}
HUNK_HEADER = re.compile(rb"^@@ -(\d+)(?:,(\d+))? \+(\d+)(?:,(\d+))? @@")


def parse_hunks(base_blob, target_blob):
	# -U0 hunks of one text file: (start index in base, removed count, added lines, text).
	diff = git("diff", "-U0", "--diff-algorithm=patience", "--no-color", "--no-ext-diff", base_blob, target_blob)
	hunks = []
	for line in diff.split(b"\n"):
		m = HUNK_HEADER.match(line)
		if m:
			start = int(m.group(1))
			count = int(m.group(2)) if m.group(2) is not None else 1
			index = start if count == 0 else start - 1
			hunks.append([index, count, [], [], []])
		elif hunks and line.startswith(b"+") and not line.startswith(b"+++"):
			hunks[-1][2].append(line[1:])
			hunks[-1][3].append(line[1:])
		elif hunks and line.startswith(b"-") and not line.startswith(b"---"):
			hunks[-1][3].append(line[1:])
			hunks[-1][4].append(line[1:])
	# Two replacements a few structural base lines apart ("}", "return true;") are one rewrite: the new
	# code merely reuses the old code's closing lines, and must not be cut in two around them.
	base_lines = git("cat-file", "blob", base_blob).split(b"\n")
	merged = []
	for h in hunks:
		if merged and merged[-1][1] > 0 and h[1] > 0:
			prev = merged[-1]
			gap = base_lines[prev[0] + prev[1] : h[0]]
			if len(gap) <= 3 and all(g.strip() in STRUCTURAL_LINES for g in gap):
				prev[2] += gap + h[2]
				prev[4] += gap + h[4]
				prev[3] = prev[2] + prev[4]
				prev[1] = h[0] + h[1] - prev[0]
				continue
		merged.append(h)
	hunks = merged
	# A rewrite whose old and new code both end inside a scope that a kept "}" closes takes that line:
	# otherwise deleting the old code alone would leave the "}" behind.
	for h in hunks:
		while h[1] > 0 and h[2] and code_balance(h[4]) > 0 and code_balance(h[2]) > 0 and h[0] + h[1] < len(base_lines) and base_lines[h[0] + h[1]].strip() in (b"}", b"};"):
			closer = base_lines[h[0] + h[1]]
			h[1] += 1
			h[2].append(closer)
			h[4].append(closer)
			h[3] = h[2] + h[4]
	# A replacement is refined into the lines it keeps (a removed line paired with a similar added one),
	# pure deletions and pure insertions (see refine_hunk); a pure insertion is split into top-level
	# blocks (see split_blocks), each its own hunk at the same place, so one rule can take the Sky lines
	# of an #include or registration list, or the new function in front of a changed signature, and
	# leave the rest. A hunk's text (what rules match) is what it adds; a pure deletion is matched by
	# `~!` pins only and otherwise stays in the file's home patch (see assign()).
	# Entries: [base index, removed count, added lines, text rules match, parent entry or None]. A block
	# with a braced body (function, struct, enum, if) is a head, one entry per statement or member of
	# its body (recursively) and a tail; the body's entries are the head's children (see assign()).
	split = []
	for index, count, added, text, removed in hunks:
		first_new = len(split)  # This hunk's entries start here.
		for piece_index, piece_count, piece_added, piece_removed in refine_hunk(index, count, added, removed):
			if piece_count == 0 and len(piece_added) > 1:
				for block in split_blocks(piece_added):
					add_structured(split, piece_index, block, None)
				continue
			if not piece_added and piece_count > 1 and all(line.startswith(b"#include ") for line in piece_removed):
				# Removed #includes, one piece each (as added ones are): a pin can then drop the one a
				# feature replaces while the base code still needs the others.
				for i, line in enumerate(piece_removed):
					split.append([piece_index + i, 1, [], match_text([line]), None])
				continue
			entry = [piece_index, piece_count, piece_added, match_text(piece_added if piece_added else piece_removed), None]
			candidates = [e for e in range(first_new, len(split)) if split[e][2]]
			if not piece_added and candidates and piece_count <= 3:
				# The old side of a small rewrite (a declaration rewritten whole) goes with the new line
				# most like it.
				old_text = b"\n".join(piece_removed)
				entry.append(max(candidates, key=lambda e: likeness(old_text, b"\n".join(split[e][2]))))
			split.append(entry)
	return split


def match_text(lines):
	"""What hunk rules match: the code of the lines without comments (string literals kept), or the
	comments when the lines hold nothing else."""
	code = []
	for line in lines:
		stripped = line.strip()
		if stripped.startswith((b"/*", b"*", b"//")):
			continue
		code.append(re.sub(rb'"(?:\\.|[^"\\])*"|//.*', lambda m: m.group(0) if m.group(0).startswith(b'"') else b"", line))
	if any(c.strip() for c in code):
		return code
	return list(lines)


def add_structured(out, index, block, parent):
	"""Appends a pure-insertion block at index: as one entry, or, when it opens a braced body, as its
	head, its body's blocks (children of the head, recursively) and its tail (the closing lines)."""

	def code(line):
		return re.sub(rb'"(?:\\.|[^"\\])*"', b"", line.split(b"//")[0]).strip()

	def balance(line):
		c = code(line)
		return sum(c.count(x) for x in b"([{") - sum(c.count(x) for x in b")]}")

	head_end = tail_start = None
	depth = 0
	for i, line in enumerate(block):
		if code(line).startswith(b"#"):
			continue
		before = depth
		depth += balance(line)
		if head_end is None:
			if depth > 0 and code(line).endswith(b"{") and before == depth - 1:
				head_end = i
			elif depth > 0 and not code(line).endswith(b"{"):
				break  # A multi-line call or expression: one entry.
		elif depth == 0:
			tail_start = i
			break
	if head_end is None or tail_start is None or tail_start <= head_end + 1:
		out.append([index, 0, block, match_text(block), parent])
		return
	head = len(out)
	out.append([index, 0, block[: head_end + 1], match_text(block[: head_end + 1]), parent])
	for child in split_blocks(block[head_end + 1 : tail_start]):
		add_structured(out, index, child, head)
	out.append([index, 0, block[tail_start:], [], head])


def code_of(line):
	return re.sub(rb'"(?:\\.|[^"\\])*"', b"", line.split(b"//")[0]).strip()


def code_balance(lines):
	total = 0
	for line in lines:
		code = re.sub(rb'"(?:\\.|[^"\\])*"', b"", line.split(b"//")[0]).strip()
		if not code.startswith((b"#", b"*", b"/*")):
			total += sum(code.count(x) for x in b"([{") - sum(code.count(x) for x in b")]}")
	return total


def likeness(a, b):
	return difflib.SequenceMatcher(None, a.strip(), b.strip(), autojunk=False).ratio()


def similar(a, b):
	a, b = a.strip(), b.strip()
	if len(a) < 4 or len(b) < 4:
		return a == b and len(a) > 1  # A lone brace or blank line is no evidence of an edit.
	if a == b:
		return True
	return difflib.SequenceMatcher(None, a, b, autojunk=False).ratio() >= 0.6


def refine_hunk(index, count, added, removed):
	"""Splits one -U0 hunk (count base lines from index replaced by added) into pieces (index, count,
	added, removed) in base order. When the shorter side pairs line by line with a run of similar lines
	of the longer side (edited lines: a changed signature under a new function, a changed call amid new
	statements), those pairs are 1-line replacements and the rest of the longer side pure insertions or
	deletions around them; otherwise the hunk is a rewrite: one insertion, then one deletion. Any
	subset of the pieces applies to the base."""
	if count == 0 or not added:
		return [(index, count, added, removed)]
	n, m = len(removed), len(added)
	pieces = []
	if m >= n:
		# The run of added lines most like the removed ones (a changed signature pairs with itself, not
		# with a new function's signature above it).
		runs = [j for j in range(m - n + 1) if all(similar(removed[i], added[j + i]) for i in range(n))]
		runs.sort(key=lambda j: -sum(likeness(removed[i], added[j + i]) for i in range(n)))
		for j in runs[:1]:
				if j:
					pieces.append((index, 0, added[:j], []))
				pieces += [(index + i, 1, [added[j + i]], [removed[i]]) for i in range(n)]
				rest = added[j + n :]
				# An edited line that opens a multi-line expression (not a block) keeps its continuation.
				last = pieces[-1]
				while rest and code_balance(last[2]) > 0 and not code_of(last[2][-1]).endswith(b"{"):
					last = (last[0], last[1], last[2] + [rest[0]], last[3])
					rest = rest[1:]
				pieces[-1] = last
				if rest:
					pieces.append((index + n, 0, rest, []))
				return pieces
	else:
		runs = [i0 for i0 in range(n - m + 1) if all(similar(removed[i0 + t], added[t]) for t in range(m))]
		runs.sort(key=lambda i0: -sum(likeness(removed[i0 + t], added[t]) for t in range(m)))
		for i0 in runs[:1]:
				if i0:
					pieces.append((index, i0, [], removed[:i0]))
				pieces += [(index + i0 + t, 1, [added[t]], [removed[i0 + t]]) for t in range(m)]
				if i0 + m < n:
					pieces.append((index + i0 + m, n - i0 - m, [], removed[i0 + m :]))
				return pieces
	# A rewrite: the new text is one insertion and the old one deletion, each free to go to its own patch.
	return [(index, 0, added, []), (index, count, [], removed)]


def split_blocks(lines):
	"""Blocks of inserted lines that can move between patches on their own. A line starts a new block when
	nothing is open in the current one ((, [, { all closed) and it is not indented deeper than the current
	block's first line; deeper lines, matched closing brackets and #if ... #endif continue it; a comment
	heads the block after it; a closing bracket with nothing open closes a scope of the base text and goes
	with the next block (which reopens one). Function bodies, enums and calls therefore never split."""

	def indent(line):
		return len(line) - len(line.lstrip())

	def balance(stripped):
		code = re.sub(rb'"(\\.|[^"\\])*"', b"", stripped.split(b"//")[0])
		return sum(code.count(c) for c in b"([{") - sum(code.count(c) for c in b")]}")

	blocks = []
	pending = []
	first_indent = 0
	open_count = 0
	preprocessor = 0
	for line in lines:
		stripped = line.strip()
		if not stripped:
			(blocks[-1] if blocks and not pending else pending).append(line)
			continue
		if not blocks or (preprocessor == 0 and open_count <= 0 and indent(line) <= first_indent):
			if blocks and stripped.startswith((b"}", b")", b"]")) and balance(stripped) < 0 and not re.search(rb"[({[]", stripped):
				pending.append(line)  # Closes a scope of the base text: goes with the block that reopens one.
				continue
			if stripped.startswith((b"//", b"/*", b"*")):
				pending.append(line)
				continue
			blocks.append(pending + [line])
			pending = []
			first_indent = indent(line)
			open_count = 0
		else:
			blocks[-1].extend(pending + [line])
			pending = []
		if re.match(rb"#\s*if", stripped):
			preprocessor += 1
		elif re.match(rb"#\s*endif", stripped):
			preprocessor = max(0, preprocessor - 1)
		elif not stripped.startswith(b"#"):
			open_count += balance(stripped)
	if pending:
		if blocks:
			blocks[-1].extend(pending)
		else:
			blocks.append(pending)
	return blocks

def apply_hunks(base_bytes, hunks, chosen, target_bytes):
	if len(chosen) == len(hunks):
		return target_bytes
	lines = base_bytes.split(b"\n")
	out = []
	pos = 0
	for i, (index, count, added) in enumerate(h[:3] for h in hunks):
		if i not in chosen:
			continue
		out.extend(lines[pos:index])
		out.extend(added)
		pos = index + count
	out.extend(lines[pos:])
	return b"\n".join(out)


class Plan:
	def __init__(self, target):
		self.base = open(os.path.join(ROOT, "patches", "BASE")).read().strip()
		self.target = git("rev-parse", target).decode().strip()
		self.patches, self.excludes, self.covers, renames, self.generated, self.errors = parse_manifest(MANIFEST)
		self.changed = changed_paths(self.base, self.target)
		self.base_ids = blob_ids(self.base, None)
		self.target_ids = blob_ids(self.target, None)
		# Moves: NEW's hunks are computed against OLD's BASE text; OLD goes away with NEW.
		self.moved_from = {}
		out = git("diff", "-M", "--name-status", "-z", "--diff-filter=R", self.base, self.target).split(b"\0")
		i = 0
		while i + 2 < len(out):
			self.moved_from[out[i + 2].decode()] = out[i + 1].decode()
			i += 3
		for old, new in renames:
			if self.changed.get(old) != "D" or self.changed.get(new) != "A":
				self.errors.append("manifest: `= %s %s` is not a deleted and an added path" % (old, new))
			else:
				self.moved_from[new] = old
		self.assign()

	def covered(self, path):
		return not self.covers or any(path == c or path.startswith(c + "/") for c in self.covers)

	def assign(self):
		self.warnings = []
		self.home = {}
		self.unassigned = []
		self.excluded = []
		for path in sorted(self.changed):
			if any(r.match(path) for r in self.excludes):
				self.excluded.append(path)
				continue
			for k, p in enumerate(self.patches):
				if any(r.match(path) for _, r in p.globs):
					self.home[path] = k
					break
			else:
				if self.covered(path):
					self.unassigned.append(path)
		moved_old = {old: new for new, old in self.moved_from.items()}
		for old, new in moved_old.items():
			if new in self.home:
				if old in self.home and self.home[old] != self.home[new]:
					self.errors.append("manifest: %s moves to %s; the two must share a patch" % (old, new))
				self.home[old] = self.home[new]
				if old in self.unassigned:
					self.unassigned.remove(old)
		for k, p in enumerate(self.patches):
			for pattern, r in p.globs:
				if not any(r.match(path) for path in self.changed):
					# A warning, not an error: a pattern may name files another branch is about to bring.
					self.warnings.append("%s: `+ %s` matches no path changed since BASE" % (p.line, pattern))
		# Hunk rules: a split file's hunks go to the first later patch whose rule matches them.
		self.split = {}
		for k, p in enumerate(self.patches):
			for path, regex, pin in p.hunk_rules:
				if path not in self.home:
					self.errors.append("%s: hunk rule for %s, which no patch claims" % (p.line, path))
					continue
				if self.home[path] > k or (self.home[path] == k and not pin):
					self.errors.append("%s: hunk rule for %s must come after its home patch (or be a `~!` pin there)" % (p.line, path))
					continue
				if self.changed[path] != "M" and path not in self.moved_from:
					self.errors.append("%s: hunk rules apply to modified files only: %s" % (p.line, path))
					continue
				self.split.setdefault(path, []).append((k, regex, pin))
		self.hunks = {}
		self.hunk_patch = {}
		for path, rules in self.split.items():
			# Pins first in manifest order, then ordinary rules latest patch first.
			rules = [r for r in rules if r[2]] + sorted([r for r in rules if not r[2]], key=lambda r: -r[0])
			hunks = parse_hunks(self.base_ids[self.moved_from.get(path, path)][1], self.target_ids[path][1])
			# An entry goes to the first rule matching its text; a body's entry (a statement, a member) goes
			# to its head's patch when no rule matches it, and never before its head.
			owners = []
			for h in hunks:
				text = b"\n".join(h[3]).decode("utf-8", errors="replace")
				owner = self.home[path] if h[4] is None else owners[h[4]]
				if len(h) > 5:
					owner = owners[h[5]]
				deletion = not h[2]
				for k, regex, pin in rules:
					# What a patch removes moves only by a pin: old code names the features it predates.
					if text.strip() and (pin or not deletion) and regex.search(text):
						owner = k if h[4] is None else max(k, owner)
						break
				owners.append(owner)
			self.hunks[path] = hunks
			self.hunk_patch[path] = owners
			for k, regex, pin in rules:
				if k not in owners:
					self.warnings.append("%s: hunk rule %s /%s/ matches no hunk" % (self.patches[k].line, path, regex.pattern))
		for path, k in self.home.items():
			self.patches[k].files.append(path)
		for path, owners in self.hunk_patch.items():
			for k in sorted(set(owners)):
				if k != self.home[path]:
					self.patches[k].files.append(path)
		for p in self.patches:
			p.files.sort()

	def states(self):
		"""Yields (k, {path: (mode, bytes) or None}) for each patch: the files it changes."""
		needed = []
		for path in self.split:
			needed += [self.base_ids[self.moved_from.get(path, path)][1], self.target_ids[path][1]]
		blobs = read_blobs(needed)
		for k, p in enumerate(self.patches):
			changes = {}
			for path in p.files:
				if path in self.split:
					chosen = {i for i, owner in enumerate(self.hunk_patch[path]) if owner <= k}
					mode = self.target_ids[path][0]
					data = apply_hunks(blobs[self.base_ids[self.moved_from.get(path, path)][1]], self.hunks[path], chosen, blobs[self.target_ids[path][1]])
					changes[path] = (mode, data)
				elif path in self.target_ids:
					changes[path] = self.target_ids[path]
				else:
					changes[path] = None
			yield k, changes


def write_series(plan, out_dir):
	env = dict(os.environ)
	os.makedirs(out_dir, exist_ok=True)
	index_file = os.path.join(out_dir, ".index.tmp")
	env["GIT_INDEX_FILE"] = index_file
	env["GIT_AUTHOR_NAME"], env["GIT_AUTHOR_EMAIL"], env["GIT_AUTHOR_DATE"] = AUTHOR
	env["GIT_COMMITTER_NAME"], env["GIT_COMMITTER_EMAIL"], env["GIT_COMMITTER_DATE"] = AUTHOR
	git("read-tree", plan.base, env=env)
	parent = plan.base
	commits = []
	for k, changes in plan.states():
		p = plan.patches[k]
		lines = []
		for path, value in sorted(changes.items()):
			if value is None:
				lines.append("0 %s\t%s" % ("0" * 40, path))
				continue
			mode, data = value
			if isinstance(data, bytes):
				sha = git("hash-object", "-w", "--stdin", input_bytes=data).decode().strip()
			else:
				sha = data
			lines.append("%s %s\t%s" % (mode, sha, path))
		git("update-index", "--index-info", input_bytes=("\n".join(lines) + "\n").encode(), env=env)
		tree = git("write-tree", env=env).decode().strip()
		message = p.subject + "\n\n" + "\n".join(p.body).strip("\n") + "\n"
		parent = git("commit-tree", tree, "-p", parent, input_bytes=message.encode(), env=env).decode().strip()
		commits.append((k, parent))
	os.remove(index_file)
	final_tree = git("rev-parse", parent + "^{tree}").decode().strip()
	# One folder per series, numbered within it in application order.
	by_series = []
	for k, commit in commits:
		s = plan.patches[k].series
		if not by_series or by_series[-1][0] != s:
			by_series.append((s, []))
		by_series[-1][1].append(commit)
	sizes = {}
	parent_of = plan.base
	for k, commit in commits:
		counted = generated = 0
		for row in git("diff", "--numstat", "--no-renames", parent_of, commit).decode().splitlines():
			added, removed, path = row.split("\t", 2)
			n = (int(added) if added != "-" else 0) + (int(removed) if removed != "-" else 0)
			if any(r.match(path) for r in plan.generated):
				generated += n
			else:
				counted += n
		sizes[commit] = (counted, generated)
		parent_of = commit
	index_lines = []
	largest = (0, "")
	prev = plan.base
	for n, (s, series_commits) in enumerate(by_series):
		folder = os.path.join(out_dir, "%d-%s" % (n, s))
		os.makedirs(folder, exist_ok=True)
		git("format-patch", "--quiet", "--zero-commit", "-M", "--full-index", "--signature=godot-area", "--no-numbered",
				"-o", folder, "%s..%s" % (prev, series_commits[-1]))
		prev = series_commits[-1]
		for name, commit in zip(sorted(os.listdir(folder)), series_commits):
			counted, generated = sizes[commit]
			extra = " + %d generated" % generated if generated else ""
			index_lines.append("%d-%s/%s  %d lines%s" % (n, s, name, counted, extra))
			largest = max(largest, (counted, "%d-%s/%s" % (n, s, name)))
	with open(os.path.join(out_dir, "INDEX"), "w", encoding="utf-8") as f:
		f.write("# Application order (generated by misc/scripts/make_patch_series.sh from patches/manifest.txt).\n")
		f.write("# base %s\n" % plan.base)
		f.write("\n".join(index_lines) + "\n")
		f.write("largest %d changed lines (generated tables excluded): %s\n" % largest)
	return parent, final_tree


INCLUDE = re.compile(rb'^\s*#\s*include\s+"([^"]+)"', re.M)
SOURCE_EXT = (".cpp", ".h", ".inc", ".glsl")
SHADERS = "servers/rendering/renderer_rd/shaders"


def unconditional_includes(content):
	# Quoted includes outside #if/#ifdef blocks (a conditional one, such as the shapes code under
	# USE_AREA_SHAPES, is only resolved when a later patch defines its condition).
	found = []
	depth = 0
	for line in content.split(b"\n"):
		stripped = line.strip()
		if re.match(rb"#\s*if", stripped):
			depth += 1
		elif re.match(rb"#\s*endif", stripped):
			depth = max(0, depth - 1)
		elif depth == 0:
			m = INCLUDE.match(line)
			if m and not re.match(rb"#\s*ifndef", stripped):
				found.append(m.group(1).decode())
	# Include guards (#ifndef X / #define X ... #endif around the whole file) are not conditions.
	return found if found or b"#include" not in content else guarded_includes(content)


def guarded_includes(content):
	lines = [l.strip() for l in content.split(b"\n")]
	first = next((i for i, l in enumerate(lines) if l.startswith(b"#")), None)
	if first is None or not re.match(rb"#\s*ifndef\s+\w+", lines[first]) or not re.match(rb"#\s*define", lines[first + 1] if first + 1 < len(lines) else b""):
		return []
	return unconditional_includes(b"\n".join(lines[first + 2 : len(lines) - 1 - [l for l in reversed(lines)].index(next(l for l in reversed(lines) if l.startswith(b"#endif")))]))


def include_check(plan):
	"""After each patch, every quoted #include in a C++/GLSL file must name a file of that tree."""
	files = {p: v for p, v in plan.base_ids.items()}
	cache = {}
	problems = []
	# Contents needed: every source file of BASE and of the target.
	shas = [v[1] for p, v in list(plan.base_ids.items()) + list(plan.target_ids.items()) if p.endswith(SOURCE_EXT)]
	blobs = read_blobs(shas)
	for k, changes in plan.states():
		for path, value in changes.items():
			if value is None:
				files.pop(path, None)
			else:
				files[path] = value
		present = set(files)
		for path, (mode, data) in files.items():
			if not path.endswith(SOURCE_EXT):
				continue
			content = data if isinstance(data, bytes) else blobs.get(data)
			if content is None:
				content = read_blobs([data])[data]
			key = (path, content if isinstance(data, bytes) else data)
			if key not in cache:
				# C++: every include (the build defines its conditions, e.g. GODOT_AREA_EDITOR_WINDOW);
				# GLSL: only unconditional ones (a variant's #ifdef decides at run time).
				cache[key] = unconditional_includes(content) if path.endswith(".glsl") else [m.decode() for m in INCLUDE.findall(content)]
			for inc in cache[key]:
				if inc.endswith(".gen.h") or (inc.endswith(".glsl") and not path.endswith(".glsl")):
					continue  # Generated, or GLSL text inside a C++ test's string.
				folder = os.path.dirname(path)
				candidates = [os.path.normpath(os.path.join(folder, inc)), inc]
				if path.endswith(".glsl") or path.startswith(SHADERS):
					candidates.append(SHADERS + "/" + inc)
				if not any(c in present for c in candidates) and not os.path.exists(os.path.join("/usr/include", inc)):
					problems.append((k, path, inc))
	return problems


def main():
	args = sys.argv[1:]
	if not args or args[0] not in ("write", "check", "plan", "compare"):
		sys.exit(__doc__)
	target = "HEAD"
	if "--target" in args:
		i = args.index("--target")
		target = args[i + 1]
		del args[i : i + 2]
	plan = Plan(target)
	for e in plan.errors:
		print("manifest: " + e, file=sys.stderr)
	for w in plan.warnings:
		print("manifest: warning: " + w, file=sys.stderr)
	if args[0] == "plan":
		for k, p in enumerate(plan.patches):
			print("%02d [%s] %s" % (k + 1, p.series, p.subject))
			for path in p.files:
				print("      " + path + (" (hunks)" if path in plan.split else ""))
		return 1 if plan.errors else 0
	if args[0] == "write":
		out_dir = args[1]
		tip, tree = write_series(plan, out_dir)
		print(tip)
		return 1 if plan.errors else 0
	if args[0] == "compare":
		carried = set(plan.home)
		differ = [p for p in git("diff", "--no-renames", "--name-only", "-z", args[1], plan.target).decode().split("\0") if p in carried]
		# A path that differs from the target but no patch carries: changed after the series was written.
		stale = [p for p in git("diff", "--no-renames", "--name-only", "-z", args[1], plan.target).decode().split("\0")
				if p and p not in carried and not any(r.match(p) for r in plan.excludes)]
		for path in differ:
			print("differs: " + path, file=sys.stderr)
		for path in stale:
			print("not in the series: " + path, file=sys.stderr)
		print("compare: %d carried paths, %d differ, %d changed paths no patch carries" % (len(carried), len(differ), len(stale)))
		return 1 if differ or stale else 0
	if args[0] == "check":
		status = 1 if plan.errors else 0
		for path in plan.unassigned:
			print("unassigned: %s (add it to a patch in patches/manifest.txt)" % path, file=sys.stderr)
			status = 1
		problems = include_check(plan)
		first = {}
		for k, path, inc in problems:
			first.setdefault((path, inc), []).append(k)
		for (path, inc), ks in sorted(first.items(), key=lambda item: item[1][0]):
			k = ks[0]
			print("include: patches %02d-%02d (from %s): %s includes \"%s\", not there yet" % (k + 1, ks[-1] + 1, plan.patches[k].subject, path, inc), file=sys.stderr)
		for k, path, inc in []:
			print("include: after patch %02d (%s) %s includes missing \"%s\"" % (k + 1, plan.patches[k].subject, path, inc), file=sys.stderr)
		if problems and status == 0:
			status = 3  # Only includes: make_patch_series.sh still writes the series.
		print("manifest: %d patches, %d paths assigned, %d split by hunks, %d excluded, %d unassigned, %d unresolved includes"
				% (len(plan.patches), len(plan.home), len(plan.split), len(plan.excluded), len(plan.unassigned), len(problems)))
		return status


if __name__ == "__main__":
	sys.exit(main())
