# lab.awk - colour functions shared by the chart scripts (styles.sh, the
# shade test in tests/plots_cli.sh): sRGB hex <-> CIELAB (D65), the
# CIE76 delta-E, and the shades of one hue group.
#   lab_of(hex)           sets LAB_L, LAB_A, LAB_B
#   hex_of(L, a, b)       the nearest sRGB colour (chroma reduced, hue and
#                         lightness kept, until it lies in the gamut)
#   delta_e(hex1, hex2)   CIE76 distance
#   lab_shade(hex, s, n)  member s of n of the group of hue hex: lightness
#                         26 + 14 (s - 1) (26 to 82; from the sixth
#                         member on, again, with the hue turned by 40
#                         degrees more) and hue turned in steps of 11
#                         degrees, so that members differ by a delta-E of
#                         at least 15 and a member's shade does not depend
#                         on the group's size; n = 1: the hue itself
function lab_hx(c) { return index("0123456789abcdef", tolower(c)) - 1 }
function lab_lin(c) { c /= 255; return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ^ 2.4 }
function lab_gam(c) { c = c <= 0.0031308 ? 12.92 * c : 1.055 * c ^ (1 / 2.4) - 0.055; return c * 255 }
function lab_f(t) { return t > 0.008856 ? t ^ (1 / 3) : 7.787 * t + 16 / 116 }
function lab_fi(t) { return t ^ 3 > 0.008856 ? t ^ 3 : (t - 16 / 116) / 7.787 }
function lab_of(h,   r, g, b, X, Y, Z) {
	sub(/^#/, "", h)
	r = lab_lin(lab_hx(substr(h, 1, 1)) * 16 + lab_hx(substr(h, 2, 1)))
	g = lab_lin(lab_hx(substr(h, 3, 1)) * 16 + lab_hx(substr(h, 4, 1)))
	b = lab_lin(lab_hx(substr(h, 5, 1)) * 16 + lab_hx(substr(h, 6, 1)))
	X = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
	Y = 0.2126 * r + 0.7152 * g + 0.0722 * b
	Z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883
	LAB_L = 116 * lab_f(Y) - 16; LAB_A = 500 * (lab_f(X) - lab_f(Y)); LAB_B = 200 * (lab_f(Y) - lab_f(Z))
}
# lab_rgb(L, a, b): sets LAB_R, LAB_G, LAB_BL (0..255, unclamped); 1 when in gamut
function lab_rgb(L, a, b,   fy, X, Y, Z) {
	fy = (L + 16) / 116
	X = 0.95047 * lab_fi(fy + a / 500); Y = lab_fi(fy); Z = 1.08883 * lab_fi(fy - b / 200)
	LAB_R = 3.2406 * X - 1.5372 * Y - 0.4986 * Z
	LAB_G = -0.9689 * X + 1.8758 * Y + 0.0415 * Z
	LAB_BL = 0.0557 * X - 0.2040 * Y + 1.0570 * Z
	return LAB_R >= 0 && LAB_R <= 1 && LAB_G >= 0 && LAB_G <= 1 && LAB_BL >= 0 && LAB_BL <= 1
}
function hex_of(L, a, b,   k) {
	for (k = 1; k >= 0; k -= 0.02) if (lab_rgb(L, a * k, b * k)) break
	if (k < 0) lab_rgb(L, 0, 0)
	return sprintf("#%02x%02x%02x", lab_gam(LAB_R < 0 ? 0 : LAB_R) + 0.5, lab_gam(LAB_G < 0 ? 0 : LAB_G) + 0.5, lab_gam(LAB_BL < 0 ? 0 : LAB_BL) + 0.5)
}
function delta_e(h1, h2,   L1, a1, b1) {
	lab_of(h1); L1 = LAB_L; a1 = LAB_A; b1 = LAB_B
	lab_of(h2)
	return sqrt((L1 - LAB_L) ^ 2 + (a1 - LAB_A) ^ 2 + (b1 - LAB_B) ^ 2)
}
function lab_shade(h, s, n,   L, C, hu, a) {
	if (n <= 1) return tolower(h)
	lab_of(h)
	L = 26 + ((s - 1) % 5) * 14
	C = sqrt(LAB_A ^ 2 + LAB_B ^ 2); hu = atan2(LAB_B, LAB_A)
	a = hu + ((s - 3) * 11 + int((s - 1) / 5) * 40) * 3.14159265 / 180
	return hex_of(L, C * cos(a), C * sin(a))
}
