#!/usr/bin/python3
# godot-area: SPIR-V instruction counts of the per-light shading code, per area method vs the omni/spot loops.
#
#   bin/godot-area bench --sweep methods --spirv-sources DIR
#   /usr/bin/python3 misc/scripts/spirv_method_counts.py DIR
#
# Each DIR/*.frag is the fully preprocessed fragment source the renderer compiles (area_<METHOD>.frag:
# the area-light colour variant with exactly that method; area_<METHOD>_shapes.frag: the same with the
# disk / sphere / tube code; base.frag: the colour variant without area lights). Each is compiled with
# glslangValidator -V (glslang's own code generation, no optimiser) and disassembled with spirv-dis. The count of a function is its own instructions (OpFunction ..
# OpFunctionEnd, without OpLabel/OpFunctionParameter/OpVariable/OpLine/OpNoLine) plus, for every
# OpFunctionCall, the count of the callee: the size of the fully inlined call tree, i.e. the code one
# light costs. Roots: light_process_area_method (the area dispatch, one method compiled in) and
# light_process_omni / light_process_spot. A second column gives the same after spirv-opt -O of a
# module whose only entry is the whole shader (total fragment instructions), for reference.
import os
import re
import subprocess
import sys
import tempfile

SKIP = {"OpLabel", "OpFunctionParameter", "OpVariable", "OpLine", "OpNoLine", "OpFunction", "OpFunctionEnd"}


def disassemble(spv):
	return subprocess.run(["spirv-dis", "--raw-id", spv], check=True, capture_output=True, text=True).stdout.splitlines()


def function_sizes(lines):
	names, funcs, cur = {}, {}, None
	for line in lines:
		m = re.match(r'\s*OpName (%\d+) "(.*)"', line)
		if m:
			names[m.group(1)] = m.group(2)
			continue
		m = re.match(r"\s*(%\d+) = OpFunction ", line)
		if m:
			cur = m.group(1)
			funcs[cur] = {"own": 0, "calls": []}
			continue
		if cur is None:
			continue
		if "OpFunctionEnd" in line:
			cur = None
			continue
		op = re.search(r"\b(Op\w+)", line)
		if not op or op.group(1) in SKIP:
			continue
		funcs[cur]["own"] += 1
		if op.group(1) == "OpFunctionCall":
			funcs[cur]["calls"].append(line.split("OpFunctionCall")[1].split()[1])
	memo = {}

	def total(f):
		if f not in memo:
			memo[f] = funcs[f]["own"] + sum(total(c) for c in funcs[f]["calls"] if c in funcs)
		return memo[f]

	return {names.get(f, f): total(f) for f in funcs}


def count_module(lines):
	return sum(1 for l in lines if re.search(r"\bOp\w+", l) and not re.search(r"\bOp(Name|MemberName|Decorate|MemberDecorate|Line|NoLine|Source|String|ModuleProcessed)\b", l))


def compile_one(path, tmp):
	spv = os.path.join(tmp, os.path.basename(path) + ".spv")
	subprocess.run(["glslangValidator", "-V", "-S", "frag", "-o", spv, path], check=True, capture_output=True, text=True)
	opt = spv + ".opt"
	subprocess.run(["spirv-opt", "-O", spv, "-o", opt], check=True, capture_output=True, text=True)
	return disassemble(spv), disassemble(opt)


def root(sizes, prefix):
	hits = [v for k, v in sizes.items() if k.startswith(prefix + "(")]
	return max(hits) if hits else None


def main():
	if len(sys.argv) < 2:
		print("usage: spirv_method_counts.py DIR")
		return 2
	d = sys.argv[1]
	rows = []
	with tempfile.TemporaryDirectory() as tmp:
		raw, opt = compile_one(os.path.join(d, "base.frag"), tmp)
		sizes = function_sizes(raw)
		base_total = count_module(opt)
		rows.append(("omni (light_process_omni)", root(sizes, "light_process_omni"), base_total))
		rows.append(("spot (light_process_spot)", root(sizes, "light_process_spot"), base_total))
		for m in ["LTC", "LTC_POLYNOMIAL", "MRP", "STOCHASTIC"]:
			p = os.path.join(d, "area_%s.frag" % m)
			if not os.path.exists(p):
				continue
			raw, opt = compile_one(p, tmp)
			rows.append(("area %s (light_process_area_method)" % m, root(function_sizes(raw), "light_process_area_method"), count_module(opt)))
		# area_<METHOD>_shapes.frag: the same method with the disk / sphere / tube code (USE_AREA_SHAPES); the
		# shape branch alone is light_process_area_shape.
		for m in ["LTC", "LTC_POLYNOMIAL", "MRP", "STOCHASTIC"]:
			p = os.path.join(d, "area_%s_shapes.frag" % m)
			if not os.path.exists(p):
				continue
			raw, opt = compile_one(p, tmp)
			sizes = function_sizes(raw)
			rows.append(("area %s with shapes (light_process_area_method)" % m, root(sizes, "light_process_area_method"), count_module(opt)))
			rows.append(("area %s, shape branch (light_process_area_shape)" % m, root(sizes, "light_process_area_shape"), count_module(opt)))
	print("| per-light code | SPIR-V instructions, inlined call tree (glslang -V) | whole fragment shader after spirv-opt -O |")
	print("|---|---|---|")
	for name, n, total in rows:
		print("| %s | %s | %d |" % (name, n if n is not None else "n/a", total))
	return 0


if __name__ == "__main__":
	sys.exit(main())
