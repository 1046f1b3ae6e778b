# wild.awk - the body of scripts/wild.sh (which see): reads the registry
# listings and the committed runs named by -v M, A, X, S, WO, TR, C, the
# template TPL (for its <!-- para --> and <!-- fix --> blocks), and
# expands the placeholders of the file it is given.

# A CSV line into f[1..n]: fields may be quoted (no quotes inside them).
function csv(line, f,   n, i, c, q, s) {
	n = 0; s = ""; q = 0
	for (i = 1; i <= length(line); i++) {
		c = substr(line, i, 1)
		if (q) { if (c == "\"") q = 0; else s = s c }
		else if (c == "\"") q = 1
		else if (c == ",") { f[++n] = s; s = "" }
		else s = s c
	}
	f[++n] = s
	return n
}

# Reads a CSV file with a header line (lines starting with # skipped);
# col[file, name] = column index.  Returns the number of data rows,
# stored in rows[file, r, i].
function load(file,   l, n, f, k, i, r) {
	r = 0
	while ((getline l < file) > 0) {
		if (l ~ /^#/ || l == "") continue
		n = csv(l, f)
		if (!((file, "hdr") in col)) {
			for (i = 1; i <= n; i++) col[file, f[i]] = i
			col[file, "hdr"] = n
			continue
		}
		r++
		for (i = 1; i <= n; i++) rows[file, r, i] = f[i]
	}
	close(file)
	return r
}
function get(file, r, name) {
	if (!((file, name) in col)) {
		if (file == M || file == A) return "" # a registry without provenance: no engines
		print "wild: " file " has no column " name > "/dev/stderr"; exit 1
	}
	return rows[file, r, col[file, name]]
}

# A C99 hex float (as worst.csv and certify.csv print them) as a number.
function hexval(s,   neg, e, i, c, m, pos, fr) {
	neg = substr(s, 1, 1) == "-"
	if (neg || substr(s, 1, 1) == "+") s = substr(s, 2)
	if (tolower(substr(s, 1, 2)) != "0x") return neg ? -s : s + 0
	s = substr(s, 3); pos = index(s, "p"); e = substr(s, pos + 1) + 0; s = substr(s, 1, pos - 1)
	m = 0; fr = 0
	for (i = 1; i <= length(s); i++) {
		c = substr(s, i, 1)
		if (c == ".") { fr = 1; continue }
		m = m * 16 + index("0123456789abcdef", tolower(c)) - 1
		if (fr) e -= 4
	}
	return (neg ? -m : m) * 2 ^ e
}
# Whether x y z is a rounding of a real unit vector in precision p (the
# domain of the certify bounds): | |n| - 1 | <= u, with a margin.
function unitish(x, y, z, p,   r) {
	x = hexval(x); y = hexval(y); z = hexval(z)
	r = sqrt(x * x + y * y + z * z) - 1
	return (r < 0 ? -r : r) <= 1.5 * U(p)
}
function num(s) { return isbad(s) ? 1e308 * 10 : s + 0 }
function isbad(s) { return s == "inf" || s == "nan" || s == "-nan" || s == "+inf" || s == "-inf" }
function U(p) { return p == "float" ? 2 ^ -24 : 2 ^ -53 }

# A defect or bound for the table: in units of u when below 1000u.
function fmtd(v, p) {
	if (v == "") return "-"
	if (isbad(v)) return "non-finite"
	v += 0
	if (v / U(p) < 1000) return sprintf("%.3gu", v / U(p))
	return sprintf("%.3g", v)
}

function axisname(a, b, c) {
	if (a == 1 && b == 0 && c == 0) return "+x"
	if (a == -1 && b == 0 && c == 0) return "-x"
	if (a == 0 && b == 1 && c == 0) return "+y"
	if (a == 0 && b == -1 && c == 0) return "-y"
	if (a == 0 && b == 0 && c == 1) return "+z"
	if (a == 0 && b == 0 && c == -1) return "-z"
	return sprintf("(%.3g, %.3g, %.3g)", a, b, c)
}

# Every method's frame: fr[name, axis] = "b1x b1y b1z b2x b2y b2z" (numbers)
function load_axes(   r, i, n, k, s) {
	n = load(X)
	for (r = 1; r <= n; r++) {
		s = ""
		# a signed zero is the same axis: -0 and +0 compare equal
		for (i = 3; i <= 8; i++) s = s " " (rows[X, r, i] + 0 == 0 ? 0 : rows[X, r, i] + 0)
		fr[rows[X, r, 1], rows[X, r, 2]] = s
	}
}
function same_frame(a, b,   i, ax) {
	split("+x -x +y -y +z -z", ax, " ")
	for (i = 1; i <= 6; i++)
		if (!((a, ax[i]) in fr) || !((b, ax[i]) in fr) || fr[a, ax[i]] != fr[b, ax[i]] || fr[a, ax[i]] ~ /nan/) return 0
	return 1
}
function frame_at_z(m,   v) {
	if (!((m, "+z") in fr)) return "-"
	split(fr[m, "+z"], v, " ")
	return "at +z: b1 = " axisname(v[1], v[2], v[3]) ", b2 = " axisname(v[4], v[5], v[6])
}

function nan_axis(m,   i, ax, hx) {
	split("+x -x +y -y +z -z", ax, " ")
	split("0x1p+0 0x0p+0 0x0p+0|-0x1p+0 0x0p+0 0x0p+0|0x0p+0 0x1p+0 0x0p+0|0x0p+0 -0x1p+0 0x0p+0|0x0p+0 0x0p+0 0x1p+0|0x0p+0 0x0p+0 -0x1p+0", hx, "|")
	for (i = 1; i <= 6; i++)
		if ((m, ax[i]) in fr && fr[m, ax[i]] ~ /nan/) return hx[i]
	return ""
}
function load_runs(   n, r, m, p, d, e, v, k, kk) {
	# found: the largest defect with its input, from the sweep's worst
	# inputs (the 5 worst of each distribution but nonunit, kept when they
	# are roundings of unit vectors: the pole rings step past |n.z| = 1) and
	# the certify search; non-finite outputs count as infinite
	n = load(S)
	for (r = 1; r <= n; r++) {
		m = get(S, r, "method"); p = get(S, r, "precision"); d = get(S, r, "distribution")
		if (d != "nonunit") nonfin[m, p] += get(S, r, "nonfinite")
	}
	n = load(WO)
	for (r = 1; r <= n; r++) {
		m = get(WO, r, "method"); p = get(WO, r, "precision"); d = get(WO, r, "distribution")
		if (d == "nonunit") continue
		if (!unitish(get(WO, r, "nx"), get(WO, r, "ny"), get(WO, r, "nz"), p)) continue
		e = get(WO, r, "error")
		if (!((m, p) in found) || num(e) > num(found[m, p])) {
			found[m, p] = e
			input[m, p] = get(WO, r, "nx") " " get(WO, r, "ny") " " get(WO, r, "nz")
		}
	}
	# non-finite output: the sweep's worst lists finite defects only, so the
	# replayed input is the first axis where the kernel is not finite
	for (k in nonfin) {
		if (nonfin[k] == 0) continue
		split(k, kk, SUBSEP)
		v = nan_axis(kk[1])
		if (v != "") { found[k] = "nan"; input[k] = v }
	}
	n = load(TR)
	for (r = 1; r <= n; r++) speed[get(TR, r, "method"), get(TR, r, "precision")] = get(TR, r, "batch_mbases_1t")
	# C: one or more certify.csv files, space-separated; a later file's
	# whole-sphere row of a method and precision replaces an earlier one's
	nc = split(C, cf, " ")
	for (i = 1; i <= nc; i++) load_cert(cf[i])
}
function load_cert(F,   n, r, m, p, v) {
	n = load(F)
	for (r = 1; r <= n; r++) {
		if (get(F, r, "nz_lo") + 0 != -1 || get(F, r, "nz_hi") + 0 != 1 || get(F, r, "phi_lo") + 0 != 0 || get(F, r, "phi_hi") + 0 != 360) continue
		m = get(F, r, "method"); p = get(F, r, "precision")
		cbound[m, p] = get(F, r, "bound"); cstatus[m, p] = get(F, r, "status")
		v = get(F, r, "found"); cfound[m, p] = v
		if (!((m, p) in found) || num(v) > num(found[m, p])) {
			found[m, p] = v
			input[m, p] = get(F, r, "found_nx") " " get(F, r, "found_ny") " " get(F, r, "found_nz")
		}
	}
}

function load_registry(   n, r, m, i) {
	n = load(M)
	for (r = 1; r <= n; r++) {
		m = get(M, r, "name")
		meth[m] = 1; morder[++nmeth] = m; target[m] = m; precs[m] = "float and double"
		hand[m] = get(M, r, "handedness"); fam[m] = get(M, r, "family")
		if (get(M, r, "repository") == "") continue
		eng[++neng] = m; target[m] = m; isalias[m] = 0; precs[m] = "float and double"
		src[m] = get(M, r, "source"); repo[m] = get(M, r, "repository"); commit[m] = get(M, r, "commit")
		path[m] = get(M, r, "path"); lic[m] = get(M, r, "license"); sprec[m] = get(M, r, "precision")
		build[m] = get(M, r, "build"); lang[m] = get(M, r, "language"); nmethods++
	}
	n = load(A)
	for (r = 1; r <= n; r++) {
		m = get(A, r, "name")
		eng[++neng] = m; target[m] = get(A, r, "target"); isalias[m] = 1; precs[m] = get(A, r, "precisions")
		src[m] = get(A, r, "source"); repo[m] = get(A, r, "repository"); commit[m] = get(A, r, "commit")
		path[m] = get(A, r, "path"); lic[m] = get(A, r, "license"); sprec[m] = get(A, r, "precision")
		build[m] = get(A, r, "build"); lang[m] = get(A, r, "language"); note[m] = get(A, r, "note"); naliases++
		hand[m] = hand[target[m]]; fam[m] = fam[target[m]]
	}
}

# The source's own precision: whichever of float and double its text names first.
function lead(e,   s, f, d) {
	s = tolower(sprec[e]); f = index(s, "float"); d = index(s, "double")
	return (d > 0 && (f == 0 || d < f)) ? "double" : "float"
}
# Whether an alias's identity covers precision p (its target's figures
# apply); a source that has no float path (its precision reads "double
# only": Babylon.js's JavaScript numbers) has no float figures, whatever its
# float kernel (a rounding of the double row) measures.
function covers(e, p) {
	if (p == "float" && index(tolower(sprec[e]), "double only") == 1) return 0
	return !isalias[e] || index(precs[e], p) > 0
}

function proven(m, p) { return ((m, p) in cstatus) && cstatus[m, p] != "singular" && !isbad(cbound[m, p]) }
function safe(m, p) {
	return ((m, p) in cstatus) && cstatus[m, p] != "singular" && !isbad(cbound[m, p]) && cbound[m, p] / U(p) <= 16
}
# Found within 16u in the source's own precisions (both when it names
# both), nowhere non-finite nor singular.
function measured_ok(e, t,   i, p, pp, any) {
	split("float double", pp, " ")
	for (i = 1; i <= 2; i++) {
		p = pp[i]
		if (!((t, p) in found) || (index(tolower(sprec[e]), p) == 0 && p != lead(e))) continue
		any = 1
		if (isbad(found[t, p]) || num(found[t, p]) / U(p) > 16 || nonfin[t, p] > 0 || cstatus[t, p] == "singular") return 0
	}
	return any
}
function fails(e,   t) {
	t = target[e]
	if (!covers(e, "float")) return 0
	return num(found[t, "float"]) > 1e-3 || isbad(found[t, "float"]) || nonfin[t, "float"] > 0 || cstatus[t, "float"] == "singular"
}

# The fix: none (proven), a proven method that keeps the frame at the six
# axes, or the hand-written change of the template.  fixm[e] = the method
# whose bound is quoted ("" for a hand-written change).
function choose_fix(e,   t, i, c, best, p) {
	t = target[e]; p = lead(e)
	if (safe(t, "float") && (safe(t, "double") || !((t, "double") in cstatus))) {
		fixm[e] = t
		return "none needed: proven"
	}
	# a method proven within 16u in both precisions with the same frame, the
	# tightest in the engine's precision; or this project's fix of the
	# engine (NAME_fixed), proven, when no such method exists
	best = ""
	for (i = 1; i <= nmeth; i++) {
		c = morder[i]
		if (c == t || !safe(c, "float") || !safe(c, "double") || !same_frame(c, t)) continue
		if (best == "" || cbound[c, p] + 0 < cbound[best, p] + 0) best = c
	}
	c = t "_fixed"
	if (best == "" && (c in meth) && proven(c, p) && same_frame(c, t)) best = c
	# measured within 16u in both precisions, but not proven so: no fix is
	# called for; a proven method with the same frame is named beside it
	if (measured_ok(e, t)) {
		fixm[e] = best
		return "none needed by measurement (found within 16u; the bound does not close, see below)" \
		       (best == "" ? "" : "; proven with the same frame: `" best "`")
	}
	if (best != "") { fixm[e] = best; return "`" best "`, the same frame at +-x, +-y, +-z" }
	fixm[e] = ""
	c = (e in fixtext) ? e : (t in fixtext) ? t : ""
	if (c == "") return "no proven method keeps this frame"
	if (c in fixmeth) {
		if (!(fixmeth[c] in meth)) { print "wild: the fix of " c " names no method " fixmeth[c] > "/dev/stderr"; bad = 1 }
		fixm[e] = fixmeth[c]
	}
	return fixtext[c]
}
function fixbound(e, p,   f) {
	f = fixm[e]
	if (f == "" || !((f, p) in cbound) || !proven(f, p)) return "not proven"
	return "<= " fmtd(cbound[f, p], p)
}

function evalcmd(e, p) {
	if (!((target[e], p) in input) || !covers(e, p)) return ""
	return "onbstudy eval --precision " p " --methods " e " " input[target[e], p]
}

# One engine's figure, for {{W name precision key}}.
function W(e, p, k,   t) {
	if (!(e in target)) { print "wild: no engine " e > "/dev/stderr"; bad = 1; return "?" }
	t = target[e]
	if (k == "found") return covers(e, p) && ((t, p) in found) ? fmtd(found[t, p], p) : "-"
	if (k == "bound") return covers(e, p) && ((t, p) in cstatus) ? (cstatus[t, p] == "singular" ? "singular" : isbad(cbound[t, p]) ? "not bounded" : "<= " fmtd(cbound[t, p], p)) : "-"
	if (k == "input") return covers(e, p) && ((t, p) in input) ? input[t, p] : "-"
	if (k == "eval") return evalcmd(e, p)
	if (k == "speed") return covers(e, p) && ((t, p) in speed) ? sprintf("%.0f", speed[t, p]) : "-"
	if (k == "fix") return fix[e]
	if (k == "fixbound") return fixbound(e, p)
	if (k == "hand") return hand[e]
	if (k == "frame") return frame_at_z(t)
	if (k == "commit") return commit[e]
	if (k == "path") return path[e]
	if (k == "repository") return repo[e]
	if (k == "source") return src[e]
	print "wild: bad key " k > "/dev/stderr"; bad = 1; return "?"
}

function cell_found(e,   s, p, i, pp) {
	split("float double", pp, " "); s = ""
	for (i = 1; i <= 2; i++) {
		p = pp[i]
		s = s (i > 1 ? " / " : "") W(e, p, "found")
		if (covers(e, p) && nonfin[target[e], p] > 0) s = s " (non-finite on " nonfin[target[e], p] ")"
	}
	return s
}

# The order of the rows: the worst defect found in float first (a
# non-finite output counts as infinite), then in double, each as printed; a row without a
# figure in a precision sorts below every row with one; ties keep the
# registry's order.
function key(e, p,   t) {
	t = target[e]
	if (!covers(e, p) || !((t, p) in found)) return -1
	if (nonfin[t, p] > 0 || isbad(found[t, p])) return 1e308 * 10
	# as the table prints it (fmtd: 3 digits), so that equal cells tie
	if (found[t, p] / U(p) < 1000) return sprintf("%.3g", found[t, p] / U(p)) * U(p)
	return sprintf("%.3g", found[t, p]) + 0
}
function worse(a, b,   ka, kb) {
	ka = key(a, "float"); kb = key(b, "float")
	if (ka != kb) return ka > kb
	return key(a, "double") > key(b, "double")
}
# out[1..n]: the rows of a kind (methods: an engine's own arithmetic;
# aliases; findings), worst first.
function sortrows(kind, out,   i, j, n, e, tmp) {
	n = 0
	for (i = 1; i <= neng; i++) {
		e = eng[i]
		if ((kind == "methods" && isalias[e]) || (kind == "aliases" && !isalias[e]) || (kind == "findings" && !fails(e))) continue
		out[++n] = e
		for (j = n; j > 1 && worse(out[j], out[j - 1]); j--) { tmp = out[j]; out[j] = out[j - 1]; out[j - 1] = tmp }
	}
	return n
}
function tablehead() {
	return "| engine | code (repository, commit, lines, license) | source precision | family | worst defect found, float / double | proven bound, float / double | replay the worst input (source precision) | M bases/s, float / double (batch, 1 thread) | hand; frame | drop-in fix |\n" \
	       "|---|---|---|---|---|---|---|---|---|---|\n"
}
function row(e,   t, l) {
	t = target[e]; l = lead(e)
	if (!covers(e, l)) l = l == "float" ? "double" : "float"
	return "| `" e "`" (isalias[e] ? " = `" t "`, bit for bit (" precs[e] ")" : "") " | " src[e] ": " repo[e] " `" commit[e] "` " path[e] " (" lic[e] ") | " sprec[e] " | " fam[e] \
	    " | " cell_found(e) " | " W(e, "float", "bound") " / " W(e, "double", "bound") \
	    " | " (evalcmd(e, l) == "" ? "not in the committed run" : "`" evalcmd(e, l) "`") \
	    " | " W(e, "float", "speed") " / " W(e, "double", "speed") " | " sprintf("%+d", hand[e]) "; " frame_at_z(t) \
	    " | " fix[e] (fixm[e] != "" && fixm[e] != t ? ", proven " fixbound(e, "float") " / " fixbound(e, "double") : "") " |\n"
}
# The engines' own methods, worst first.
function table(   i, n, o, s) {
	n = sortrows("methods", o); s = tablehead()
	for (i = 1; i <= n; i++) s = s row(o[i])
	return s
}
# The aliases grouped by the method they are, the groups in the order of
# that method's worst defect, each group in the registry's order.
function aliasgroups(g,   i, j, n, o, ng, done) {
	n = sortrows("aliases", o); ng = 0
	for (i = 1; i <= n; i++) if (!(target[o[i]] in done)) { done[target[o[i]]] = 1; g[++ng] = target[o[i]] }
	return ng
}
function aliastable(   i, j, ng, g, s) {
	ng = aliasgroups(g); s = tablehead()
	for (i = 1; i <= ng; i++)
		for (j = 1; j <= neng; j++) if (isalias[eng[j]] && target[eng[j]] == g[i]) s = s row(eng[j])
	return s
}
# The groups in words: "`duff` (3): `cycles_duff`, `falcor`, `pasvulkan`; ..."
function aliaslist(   i, j, ng, g, s, n, l) {
	ng = aliasgroups(g); s = ""
	for (i = 1; i <= ng; i++) {
		n = 0; l = ""
		for (j = 1; j <= neng; j++) if (isalias[eng[j]] && target[eng[j]] == g[i]) { n++; l = l (n > 1 ? ", " : "") "`" eng[j] "`" }
		s = s (i > 1 ? "; " : "") "`" g[i] "` (" n "): " l
	}
	return s == "" ? "none" : s
}
# The code bases with more than one row (a second function, or a build
# that changes the bits): "blender/cycles (`cycles_cross111`, ...)".
function multirow(   i, e, r, nr, ord, cnt, lst, s, k, nm) {
	for (i = 1; i <= neng; i++) {
		e = eng[i]; r = repo[e]
		if (!(r in cnt)) ord[++nr] = r
		cnt[r]++; lst[r] = lst[r] (cnt[r] > 1 ? ", " : "") "`" e "`"
	}
	s = ""; k = 0
	for (i = 1; i <= nr; i++) {
		r = ord[i]
		if (cnt[r] < 2) continue
		nm = r; sub(/^github\.com\//, "", nm)
		s = s (k++ ? "; " : "") nm " (" lst[r] ")"
	}
	return s == "" ? "none" : s
}
# The engines' methods certify calls singular in float or double.
function singular(   i, e, s) {
	s = ""
	for (i = 1; i <= neng; i++) {
		e = eng[i]
		if (isalias[e] || (cstatus[e, "float"] != "singular" && cstatus[e, "double"] != "singular")) continue
		s = s (s == "" ? "" : ", ") "`" e "`"
	}
	return s == "" ? "none" : s
}
function repos(   i, n, seen) {
	n = 0
	for (i = 1; i <= neng; i++) if (!(repo[eng[i]] in seen)) { seen[repo[eng[i]]] = 1; n++ }
	return n
}

# Where the worst defect (a sweep's input) exceeds the proven bound: that
# input lies outside the domain certify covers (the roundings of unit
# vectors; a sweep's unit inputs are normalized in the format, |n| - 1 up
# to a few u); say so, with the largest found inside it.
function outside(t) {
	if (!proven(t, "float") || !(num(found[t, "float"]) > num(cbound[t, "float"]))) return ""
	return " over the roundings of unit vectors, where `certify` finds at most " fmtd(cfound[t, "float"], "float") \
	       " (this input, from a sweep, is normalized in float, and not among them)"
}

function findings(   i, e, s, t, n, o, pf) {
	s = ""; n = sortrows("findings", o)
	for (i = 1; i <= n; i++) {
		e = o[i]
		if (!(e in para)) { print "wild: " e " fails in float but wild.md.in has no <!-- para " e " --> block" > "/dev/stderr"; bad = 1; continue }
		t = target[e]
		s = s "### `" e "`: " src[e] "\n\n"
		s = s "- Code: " repo[e] " at `" commit[e] "`, " path[e] " (" lic[e] "); " lang[e] ", " sprec[e] "; build read: " build[e] ".\n"
		s = s "- Worst input (float): `" (evalcmd(e, "float") == "" ? "not in the committed run" : evalcmd(e, "float")) "`.\n"
		s = s "- Defect there: " W(e, "float", "found") (nonfin[t, "float"] > 0 ? "; non-finite output on " nonfin[t, "float"] " of the sampled unit inputs" : "") \
		    (cstatus[t, "float"] == "singular" ? "; `onbstudy certify`: singular (" singtext(t) ")" : "; proven bound " W(e, "float", "bound") outside(t)) ".\n"
		pf = patchof(e "_fixed", fixm[e]) ? e "_fixed" : fixm[e]   # an engine's own diff of a shared fix (nvpro_fixed.diff, "Method: q2rtx_fixed")
		s = s "- Fix: " fix[e] (fixm[e] == "" ? "" : "; `" fixm[e] "` is proven " fixbound(e, "float") " in float and " fixbound(e, "double") " in double") \
		    (patch(pf) ? "; as a change to the engine's file: [results/wild/patches/" pf ".diff](../results/wild/patches/" pf ".diff)" : "") ".\n\n"
		s = s expand(para[e]) "\n\n"
	}
	return s == "" ? "No engine is non-finite or above 1e-3 in float in the committed runs.\n" : s
}
# The findings as a short table for the README, the worst first: the
# first lim of them (all when lim is empty).
function findlist(lim,   i, e, n, o, s) {
	n = sortrows("findings", o)
	if (lim == "" || lim + 0 > n) lim = n
	s = "| engine | defect in float | replay | drop-in fix |\n|---|---|---|---|\n"
	for (i = 1; i <= lim; i++) {
		e = o[i]
		s = s "| `" e "` (" src[e] ") | " W(e, "float", "found") " | `" evalcmd(e, "float") "` | " \
		    (fixm[e] == "" ? "the change to its own lines in [docs/wild.md](docs/wild.md)" : "`" fixm[e] "`, proven " fixbound(e, "float")) " |\n"
	}
	return n == 0 ? "No engine is non-finite or above 1e-3 in float in the committed runs.\n" : s
}
# Whether results/wild/patches (PD) has a diff f whose header says it is
# the fix m ("Method: m").
function patchof(f, m,   l, r) {
	if (m == "" || PD == "") return 0
	r = 0
	while ((getline l < (PD "/" f ".diff")) > 0)
		if (l ~ ("^Method: *" m "$")) { r = 1; break }
	close(PD "/" f ".diff")
	return r
}
# Whether results/wild/patches (PD) has the fix f as a diff.
function patch(f,   l, r) {
	if (f == "" || PD == "") return 0
	r = (getline l < (PD "/" f ".diff")) > 0
	close(PD "/" f ".diff")
	return r
}
function singtext(t) { return "the kernel returns NaN, inf or a zero vector on some unit input" }

function worst(k,   i, e, b, v) {
	b = ""
	for (i = 1; i <= neng; i++) {
		e = eng[i]
		if (!covers(e, "float") || !((target[e], "float") in found)) continue
		v = num(found[target[e], "float"]); if (nonfin[target[e], "float"] > 0) v = 1e308 * 10
		if (b == "" || v > bv) { b = e; bv = v }
	}
	if (b == "") return "-"
	if (k == "name") return b
	if (k == "found") return W(b, "float", "found") (nonfin[target[b], "float"] > 0 ? ", non-finite on some inputs" : "")
	return W(b, "float", k)
}

function count(k,   i, n) {
	if (k == "engines" || k == "rows") return neng
	if (k == "repos") return repos()
	if (k == "methods") return nmethods + 0
	if (k == "aliases") return naliases + 0
	if (k == "findings") { n = 0; for (i = 1; i <= neng; i++) n += fails(eng[i]); return n }
	print "wild: bad count " k > "/dev/stderr"; bad = 1; return "?"
}

# {{TABLE half}}: every shader engine (its language GLSL, HLSL or Slang;
# methods and aliases) in binary16, as mediump and half run it on mobile
# GPUs: the whole-sphere bracket of its C row from H (results/half/
# certify/certify-half.csv, certify --precision half): the largest bound
# and found over the regions (no bound where a region is not proven), the
# regions by status, the worst input.  Generation fails when an engine's
# C row has no rows in H.
function load_half(   n, r, m, st, b, f, k) {
	if (H == "") { print "wild: no -v H (results/half/certify/certify-half.csv)" > "/dev/stderr"; exit 1 }
	n = load(H)
	for (r = 1; r <= n; r++) {
		m = get(H, r, "method"); st = get(H, r, "status"); b = get(H, r, "bound"); f = get(H, r, "found")
		hreg[m]++; hst[m, st]++
		if (st != "proven") hnob[m] = 1; else if (!((m) in hb) || b + 0 > hb[m]) hb[m] = b + 0
		if (isbad(f)) { hfi[m] = 1; hin[m] = get(H, r, "found_nx") " " get(H, r, "found_ny") " " get(H, r, "found_nz") }
		else if (!(m in hfi) && (!(m in hf) || f + 0 > hf[m])) { hf[m] = f + 0; hin[m] = get(H, r, "found_nx") " " get(H, r, "found_ny") " " get(H, r, "found_nz") }
	}
	hloaded = 1
}
function halftable(   i, e, t, s, u, o, nlist, ord, j, tmp, b, fo, st) {
	if (!hloaded) load_half()
	u = 2 ^ -11
	for (i = 1; i <= neng; i++) if (lang[eng[i]] ~ /GLSL|HLSL|Slang/) ord[++nlist] = eng[i]
	for (i = 2; i <= nlist; i++) for (j = i; j > 1 && ord[j] < ord[j - 1]; j--) { tmp = ord[j]; ord[j] = ord[j - 1]; ord[j - 1] = tmp }
	s = "| engine | language | C row | proven bound, half | found, half | bound / found | regions proven / non-finite / overflow / unbounded | replay the worst input (half) |\n|---|---|---|---:|---:|---:|---|---|\n"
	for (i = 1; i <= nlist; i++) {
		e = ord[i]; t = target[e]
		if (!(t in hreg)) { print "wild: the shader engine " e " (C row " t ") has no rows in " H > "/dev/stderr"; bad = 1; continue }
		b = (t in hnob) ? "none" : sprintf("%.4gu", hb[t] / u)
		fo = (t in hfi) ? "non-finite" : sprintf("%.4gu", hf[t] / u)
		o = ((t in hnob) || (t in hfi) || hf[t] <= 0) ? "n/a" : sprintf("%.2f", hb[t] / hf[t])
		st = (hst[t, "proven"] + 0) " / " (hst[t, "non-finite"] + 0) " / " (hst[t, "overflow"] + 0) " / " (hst[t, "unbounded"] + 0)
		s = s "| `" e "` | " lang[e] " | `" t "` | " b " | " fo " | " o " | " st " | `onbstudy eval --precision half --methods " t " " hin[t] "` |\n"
	}
	return s
}

function expand(line,   rs, rl, tok, a, nt, rep) {
	while (match(line, /\{\{[^}]*\}\}/)) {
		rs = RSTART; rl = RLENGTH
		tok = substr(line, rs + 2, rl - 4)
		nt = split(tok, a, " ")
		if (a[1] == "TABLE" && a[2] == "wild") rep = table()
		else if (a[1] == "FINDINGS") rep = findings()
		else if (a[1] == "TABLE" && a[2] == "aliases") rep = aliastable()
		else if (a[1] == "TABLE" && a[2] == "half") rep = halftable()
		else if (a[1] == "ALIASES") rep = aliaslist()
		else if (a[1] == "MULTIROW") rep = multirow()
		else if (a[1] == "SINGULAR") rep = singular()
		else if (a[1] == "FINDLIST") rep = findlist(nt > 1 ? a[2] : "")
		else if (a[1] == "COUNT" && nt == 2) rep = count(a[2])
		else if (a[1] == "W" && nt == 4) rep = W(a[2], a[3], a[4])
		else if (a[1] == "WORST" && nt == 2) rep = worst(a[2])
		else { print "wild: bad placeholder {{" tok "}}" > "/dev/stderr"; bad = 1; rep = "?" }
		line = substr(line, 1, rs - 1) rep substr(line, rs + rl)
	}
	return line
}

# The template's <!-- para NAME --> and <!-- fix NAME --> blocks.
function load_blocks(   l, name, kind, txt) {
	kind = ""
	while ((getline l < TPL) > 0) {
		if (kind == "" && match(l, /^<!-- (para [a-z0-9_]+|fix [a-z0-9_]+( [a-z0-9_]+)?) -->$/)) {
			nw = split(l, w, " "); kind = w[2]; name = w[3]; txt = ""
			if (kind == "fix" && nw == 5) fixmeth[name] = w[4]
			continue
		}
		if (kind != "" && l == "<!-- end -->") {
			if (kind == "para") para[name] = txt; else fixtext[name] = txt
			kind = ""; continue
		}
		if (kind != "") txt = txt (txt == "" ? "" : "\n") l
	}
	close(TPL)
}

BEGIN {
	load_registry(); load_axes(); load_runs(); load_blocks()
	for (i = 1; i <= neng; i++) fix[eng[i]] = choose_fix(eng[i])
	skip = 0
}
# the blocks are read above, never printed
/^<!-- (para [a-z0-9_]+|fix [a-z0-9_]+( [a-z0-9_]+)?) -->$/ { skip = 1; next }
skip && /^<!-- end -->$/ { skip = 0; next }
skip { next }
{ print expand($0) }
END { if (bad) exit 1 }
