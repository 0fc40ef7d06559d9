/* plot_heatmap.c: heat maps of a field over (r, z) with the wave fronts
 * drawn over them (`anvil map`).  See plot.h for the contract. */
#ifdef HAVE_CONFIG_H
#include "config.h"
#endif

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot.h"

/* ------------------------------------------------------------ heat maps */

static void front_add(struct plot_front *f, double r, double z)
{
	if (f->n < PLOT_FRONT_POINTS) {
		f->r[f->n] = r;
		f->z[f->n] = z;
		f->n++;
	}
}

/* Does any point of the front lie in the map's extent? */
static int front_visible(const struct plot_heatmap *hm, const struct plot_front *f)
{
	for (size_t i = 0; i < f->n; i++)
		if (f->r[i] >= hm->r_lo && f->r[i] <= hm->r_hi && f->z[i] >= hm->z_lo &&
		    f->z[i] <= hm->z_hi)
			return 1;
	return 0;
}

/* The envelope of spheres of radius R about the disk r <= r0 in the plane
 * z = zs: flat (z = zs + dir R) under the disk, a quarter circle about its
 * rim beyond; dir = +1 goes down from the surface, -1 up from the image of
 * the surface in the bottom face (the reflection). */
static void front_envelope(struct plot_heatmap *hm, enum plot_front_kind kind,
			   const char *label, double R, double r0, double zs, int dir)
{
	struct plot_front *f = &hm->fronts[hm->nfronts];
	if (hm->nfronts >= PLOT_MAX_FRONTS || !(R > 0))
		return;
	memset(f, 0, sizeof *f);
	f->kind = kind;
	snprintf(f->label, sizeof f->label, "%s", label);
	front_add(f, 0, zs + dir * R);
	for (int i = 0; i < PLOT_FRONT_POINTS - 1; i++) {
		double th = 0.5 * M_PI * i / (PLOT_FRONT_POINTS - 2);
		front_add(f, r0 + R * sin(th), zs + dir * R * cos(th));
	}
	if (front_visible(hm, f))
		hm->nfronts++;
}

void plot_heatmap_fronts(struct plot_heatmap *hm, double t, double r0, double c1,
			 double c2, double cR, double h)
{
	front_envelope(hm, PLOT_FRONT_P, "P wave, c_1 t", c1 * t, r0, 0, 1);
	front_envelope(hm, PLOT_FRONT_S, "S wave, c_2 t", c2 * t, r0, 0, 1);
	/* the reflections exist once the direct front has reached the bottom */
	if (isfinite(h) && c1 * t > h)
		front_envelope(hm, PLOT_FRONT_PP, "P reflected from the bottom", c1 * t, r0, 2 * h, -1);
	if (isfinite(h) && c2 * t > h)
		front_envelope(hm, PLOT_FRONT_SS, "S reflected from the bottom", c2 * t, r0, 2 * h, -1);
	snprintf(hm->note, sizeof hm->note,
		 "wave fronts from the patch: c_1 t = %.3g mm, c_2 t = %.3g mm, c_R t = %.3g mm",
		 c1 * t * 1e3, c2 * t * 1e3, cR * t * 1e3);
	/* Rayleigh: a tick on the surface */
	double rr = r0 + cR * t;
	if (hm->nfronts < PLOT_MAX_FRONTS && rr >= hm->r_lo && rr <= hm->r_hi && hm->z_lo == 0) {
		struct plot_front *f = &hm->fronts[hm->nfronts++];
		memset(f, 0, sizeof *f);
		f->kind = PLOT_FRONT_R;
		snprintf(f->label, sizeof f->label, "Rayleigh wave, c_R t");
		front_add(f, rr, 0);
		front_add(f, rr, 0.08 * (hm->z_hi - hm->z_lo));
	}
}

/* One line per kind of front; black on the light diverging palette,
 * magenta on the dark sequential one (white would vanish in the key). */
static const char *const front_style[PLOT_FRONT_KIND_COUNT] = {
	[PLOT_FRONT_P] = "lw 2 dt 1", [PLOT_FRONT_S] = "lw 2 dt 2",
	[PLOT_FRONT_PP] = "lw 1.5 dt 4", [PLOT_FRONT_SS] = "lw 1.5 dt 3",
	[PLOT_FRONT_R] = "lw 4 dt 1",
};

/* The largest |v|, and the range of the finite values. */
static int heat_range(const struct plot_heatmap *hm, double *lo, double *hi, double *amax)
{
	int any = 0;
	*lo = INFINITY;
	*hi = -INFINITY;
	for (size_t i = 0; hm->v && i < hm->nr * hm->nz; i++)
		if (isfinite(hm->v[i])) {
			any = 1;
			*lo = fmin(*lo, hm->v[i]);
			*hi = fmax(*hi, hm->v[i]);
		}
	*amax = fmax(fabs(*lo), fabs(*hi));
	return any;
}

static void heat_header(FILE *f, const struct plot_heatmap *hm, const struct plot_opts *o)
{
	double lo, hi, amax, dz = hm->z_hi - hm->z_lo, dr = hm->r_hi - hm->r_lo;
	heat_range(hm, &lo, &hi, &amax);
	fputs("# anvil heat map: a gnuplot script with its data inline.\n"
	      "# Render with: gnuplot THIS_FILE > map.png\n", f);
	plot_write_terminal(f, o);
	fputs("set title ", f);
	plot_put_quoted(f, o->title && o->title[0] ? o->title : hm->title);
	fputs(" noenhanced\nset xlabel 'r (mm)'\nset ylabel 'depth z (mm)'\nset cblabel ", f);
	plot_put_quoted(f, hm->cblabel);
	/* depth downwards; true proportions unless the strip is extreme */
	fprintf(f, "\nset xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\n", hm->r_lo * 1e3,
		hm->r_hi * 1e3, hm->z_hi * 1e3, hm->z_lo * 1e3);
	if (dr > 0 && dz > 0 && dz / dr > 0.2 && dz / dr < 5)
		fputs("set size ratio -1\n", f);
	fputs("set key outside bottom center horizontal\nset tics out\n", f);
	/* the note heads the key; without a front in the key, it stands alone */
	if (hm->note[0] && hm->nfronts > 0) {
		fputs("set key title ", f);
		plot_put_quoted(f, hm->note);
		fputc('\n', f);
	} else if (hm->note[0]) {
		fputs("set label 1 ", f);
		plot_put_quoted(f, hm->note);
		fputs(" at screen 0.5, screen 0.02 center font ',9'\n", f);
	}
	if (hm->diverging)
		fprintf(f, "set palette defined (0 '#2166ac', 0.5 '#f7f7f7', 1 '#b2182b')\n"
			"set cbrange [%.6g:%.6g]\n", -amax, amax > 0 ? amax : 1.0);
	else
		fputs("set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', "
		      "0.75 '#5ec962', 1 '#fde725')\n", f);
}

static void heat_data(FILE *f, const struct plot_heatmap *hm)
{
	fputs("$map << EOD\n", f);
	for (size_t iz = 0; iz < hm->nz; iz++) {
		double z = hm->nz > 1 ? hm->z_lo + (hm->z_hi - hm->z_lo) * iz / (hm->nz - 1) : hm->z_lo;
		for (size_t ir = 0; ir < hm->nr; ir++) {
			double r = hm->nr > 1 ? hm->r_lo + (hm->r_hi - hm->r_lo) * ir / (hm->nr - 1) : hm->r_lo;
			double v = hm->v[iz * hm->nr + ir];
			if (isfinite(v))
				fprintf(f, "%.6g %.6g %.6g\n", r * 1e3, z * 1e3, v);
			else
				fprintf(f, "%.6g %.6g NaN\n", r * 1e3, z * 1e3);
		}
		fputc('\n', f);
	}
	fputs("EOD\n", f);
	for (int i = 0; i < hm->nfronts; i++) {
		fprintf(f, "$front%d << EOD\n", i + 1);
		for (size_t j = 0; j < hm->fronts[i].n; j++)
			fprintf(f, "%.6g %.6g\n", hm->fronts[i].r[j] * 1e3, hm->fronts[i].z[j] * 1e3);
		fputs("EOD\n", f);
	}
}

int plot_heatmap_write(FILE *f, const struct plot_heatmap *hm, const struct plot_opts *o)
{
	double lo, hi, amax;
	if (hm->nr < 2 || hm->nz < 2 || !heat_range(hm, &lo, &hi, &amax))
		return ANVIL_EINVAL;
	heat_header(f, hm, o);
	heat_data(f, hm);
	fputs("plot $map using 1:2:3 with image notitle", f);
	for (int i = 0; i < hm->nfronts; i++) {
		fprintf(f, ", \\\n     $front%d using 1:2 with lines %s lc rgb '%s' title ", i + 1,
			front_style[hm->fronts[i].kind % PLOT_FRONT_KIND_COUNT],
			hm->diverging ? "#000000" : "#ff00ff");
		plot_put_quoted(f, hm->fronts[i].label);
	}
	fputc('\n', f);
	return fflush(f) == 0 && !ferror(f) ? ANVIL_OK : ANVIL_EIO;
}

int plot_heatmap_save(const struct plot_heatmap *hm, const struct plot_opts *o,
		      const char *path, const char *script_path, struct anvil_err *err)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *m = open_memstream(&buf, &len);
	int st = m ? plot_heatmap_write(m, hm, o) : ANVIL_ENOMEM;
	if (m && fclose(m) != 0 && !st)
		st = ANVIL_ENOMEM;
	if (st == ANVIL_EINVAL)
		anvil_err_set(err, st, "map: nothing to draw (no finite value on a grid of at least 2 x 2)");
	else if (st)
		anvil_err_set(err, st, "map: %s", anvil_strerror(st));
	else
		st = plot_emit(buf, len, o, path, script_path, err);
	free(buf);
	return st;
}
