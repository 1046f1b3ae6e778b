# mutants.awk - list the one-token mutations of include/libonb/onb.h's kernels.
#   awk -f scripts/mutants.awk include/libonb/onb.h
# prints one mutation per line, tab-separated:
#   LINE  COL  LEN  REPLACEMENT  KIND  WHERE
# (COL is 1-based; the mutant replaces LEN characters at LINE:COL).
# Region: from the reciprocal square roots to the out-of-line library.
# Comments are masked first, so nothing inside /* */ is mutated.  Kinds:
#   const   every numeric literal: its last mantissa digit changed (hex:
#           the last hex digit), so the mutant is one literal still
#   cmp     every comparison: < <-> <=, > <-> >=, and < <-> >, == <-> !=
#   sign    every + to -, every - to + (-=, +=, unary minus included)
#   conv    every (float)/(double) cast removed, every float literal's f
#           suffix dropped, sqrtf -> sqrt, every double/float type keyword
#           in a function body swapped to the other
#   cross   every a*b - c*d (a cross-product component): operands swapped
#           to c*d - a*b, and second factors exchanged to a*d - c*b
# POSIX awk only (CI's Debian 12 has mawk).
function emit(col, len, repl, kind) {
	printf "%d\t%d\t%d\t%s\t%s\t%s\n", NR, col, len, repl, kind, where
}
function isid(c) { return c ~ /[A-Za-z0-9_]/ }
function mask(line,    out, i, c, n) {
	out = ""; n = length(line)
	for (i = 1; i <= n; i++) {
		c = substr(line, i, 1)
		if (incomment) {
			if (c == "*" && substr(line, i + 1, 1) == "/") { incomment = 0; out = out "  "; i++; continue }
			out = out " "
		} else if (c == "/" && substr(line, i + 1, 1) == "*") {
			incomment = 1; out = out "  "; i++
		} else out = out c
	}
	return out
}
function consts(s,    i, n, c, j, tok, last, k, repl, d) {
	n = length(s)
	for (i = 1; i <= n; i++) {
		c = substr(s, i, 1)
		if (c !~ /[0-9]/ || (i > 1 && (isid(substr(s, i - 1, 1)) || substr(s, i - 1, 1) == "."))) continue
		if (substr(s, i, 2) == "0x" || substr(s, i, 2) == "0X") {
			j = i + 2
			while (j <= n && substr(s, j, 1) ~ /[0-9a-fA-F]/) j++
			k = j - 1
			d = substr(s, k, 1)
			emit(k, 1, (d == "0") ? "1" : (d == "1" ? "0" : (d ~ /[0-9]/ ? d - 1 : "0")), "const")
			while (j <= n && isid(substr(s, j, 1))) j++
			i = j - 1; continue
		}
		j = i
		while (j <= n && substr(s, j, 1) ~ /[0-9.]/) j++
		k = j - 1   # last mantissa character
		while (k >= i && substr(s, k, 1) == ".") k--
		d = substr(s, k, 1)
		emit(k, 1, (d == "9") ? "8" : d + 1, "const")
		if (substr(s, j, 1) ~ /[eE]/) { j++; if (substr(s, j, 1) ~ /[-+]/) j++; while (substr(s, j, 1) ~ /[0-9]/) j++ }
		if (substr(s, j, 1) == "f" && !isid(substr(s, j + 1, 1)) && index(substr(s, i, j - i), ".") > 0) {
			if (body) emit(j, 1, "", "conv")
			j++
		}
		while (j <= n && isid(substr(s, j, 1))) j++
		i = j - 1
	}
}
function ops(s,    i, n, c, c2, p) {
	n = length(s)
	for (i = 1; i <= n; i++) {
		c = substr(s, i, 1); c2 = substr(s, i + 1, 1); p = (i > 1) ? substr(s, i - 1, 1) : ""
		if (c == "<" || c == ">") {
			if (c2 == c || p == c || (c == ">" && p == "-")) continue
			if (c2 == "=") { emit(i, 2, c, "cmp"); i++; continue }
			emit(i, 1, c "=", "cmp")
			emit(i, 1, (c == "<") ? ">" : "<", "cmp")
		} else if ((c == "=" || c == "!") && c2 == "=") {
			emit(i, 2, (c == "=") ? "!=" : "==", "cmp"); i++
		} else if (c == "-" || c == "+") {
			if (c2 == ">" || c2 == c || p == c) continue
			if (p ~ /[eE]/ && i > 2 && substr(s, i - 2, 1) ~ /[0-9.]/) continue
			emit(i, 1, (c == "-") ? "+" : "-", "sign")
		}
	}
}
function convs(s,    i, n, t, w) {
	n = length(s)
	for (i = 1; i <= n; i++) {
		if (substr(s, i, 7) == "(float)") { emit(i, 7, "", "conv"); i += 6; continue }
		if (substr(s, i, 8) == "(double)") { emit(i, 8, "", "conv"); i += 7; continue }
		if (i > 1 && isid(substr(s, i - 1, 1))) continue
		if (substr(s, i, 6) == "sqrtf(") emit(i, 5, "sqrt", "conv")
		w = 0
		if (substr(s, i, 5) == "float" && !isid(substr(s, i + 5, 1))) { w = 5; t = "double" }
		if (substr(s, i, 6) == "double" && !isid(substr(s, i + 6, 1))) { w = 6; t = "float" }
		if (w) { emit(i, w, t, "conv"); i += w - 1 }
	}
}
# a*b - c*d with simple operands (identifiers, members, ->)
function crosses(s,    rest, off, re, m, a, b, c, d, parts, k) {
	re = "[A-Za-z_][A-Za-z0-9_.>-]* \\* [A-Za-z_][A-Za-z0-9_.>-]* - [A-Za-z_][A-Za-z0-9_.>-]* \\* [A-Za-z_][A-Za-z0-9_.>-]*"
	rest = s; off = 0
	while (match(rest, re)) {
		m = substr(rest, RSTART, RLENGTH)
		k = split(m, parts, " ")
		if (k == 7) {
			a = parts[1]; b = parts[3]; c = parts[5]; d = parts[7]
			emit(off + RSTART, RLENGTH, c " * " d " - " a " * " b, "cross")
			emit(off + RSTART, RLENGTH, a " * " d " - " c " * " b, "cross")
		}
		off += RSTART + RLENGTH - 1
		rest = substr(rest, RSTART + RLENGTH)
	}
}
# two spans of onb.h: the paper and renderer kernels (before the
# out-of-line library's declarations) and the engines' kernels (physics,
# geometry and math libraries, after them, up to the checked entry's
# tolerance); the second span was left out until 2fb289e: 1223 mutants
/Reciprocal square roots of Frisvad 2012/ { on = 1 }
/Out-of-line library: batch kernels and registry/ { on = 0 }
/Methods found in shipping code/ { on = 1 }
/Relative tolerance on .n.\^2 - 1 under which/ { on = 0 }
{
	s = mask($0)
	if (!on) next
	if (s ~ /^#/ && s !~ /^#define/) next
	if (s ~ /^static inline/) {
		if (match(s, /ONB__K\([A-Za-z0-9_]+\)/)) where = "onb_" substr(s, RSTART + 7, RLENGTH - 8)
		else if (match(s, /onb_[A-Za-z0-9_]+ *\(/)) where = substr(s, RSTART, RLENGTH - 1)
		sub(/ +$/, "", where)
		# only the body of a one-line function: blank its signature
		body = index(s, "{")
		if (!body) next
		s = sprintf("%" body "s", "") substr(s, body + 1)
	} else if (s ~ /^#define/) {
		if (match(s, /ONB_[A-Z_]+/)) where = substr(s, RSTART, RLENGTH)
		body = 1
	} else body = 1
	consts(s)
	ops(s)
	convs(s)
	crosses(s)
}
