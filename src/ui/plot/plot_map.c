/* plot_map.c: R_f over V0 x h as a heat map with contours (plot.h,
 * plot_rf_map): a gnuplot script with its data inline. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "plot.h"

/* A log axis over less than a decade or two gets one labelled tic (or
 * none) from gnuplot: label the swept values themselves when there are
 * few of them (ascending, as the map's axes are). */
#define MAP_TICS_MAX 10
static void map_tics(FILE *f, const char *axis, const double *x, size_t n)
{
	if (n > MAP_TICS_MAX)
		return;
	fprintf(f, "set %stics (", axis);
	for (size_t i = 0; i < n; i++)
		fprintf(f, "%s\"%.3g\" %.6g", i ? ", " : "", x[i], x[i]);
	fputs(")\n", f);
}

int plot_rf_map_write(FILE *f, const struct plot_rf_map *m, const struct plot_opts *o)
{
	int finite = 0;
	for (size_t i = 0; i < m->nv * m->nh; i++)
		finite += isfinite(m->rf[i]);
	if (m->nv < 2 || m->nh < 2 || !finite)
		return ANVIL_EINVAL;
	fputs("# anvil restitution map: a gnuplot script with its data inline.\n"
	      "# Render with: gnuplot THIS_FILE > map.png\n", f);
	plot_write_terminal(f, o);
	/* the title is anvil's (enhanced) unless the user gave one */
	fputs("set tmargin 5\nset label 1 ", f);
	plot_put_quoted(f, o->title && o->title[0] ? o->title : m->title);
	fputs(" at screen 0.5, screen 0.96 center font ',12'", f);
	fputs(o->title && o->title[0] ? " noenhanced\n" : "\n", f);
	if (m->subtitle[0]) {
		fputs("set label 2 ", f);
		plot_put_quoted(f, m->subtitle);
		fputs(" at screen 0.5, screen 0.91 center font ',9' noenhanced\n", f);
	}
	fputs("set xlabel 'impact velocity V_0 (m/s)'\nset ylabel 'layer thickness h / r_0' offset -2,0\n"
	      "set cblabel 'coefficient of restitution R_f'\nset cbrange [0:1]\n"
	      "set view map\nset logscale xy\nset tics out\nset key off\n"
	      "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', "
	      "0.75 '#5ec962', 1 '#fde725')\n"
	      "set pm3d map corners2color mean\nset contour base\n"
	      "set cntrparam levels incremental 0.1, 0.1, 0.9\n"
	      "set cntrlabel onecolor format '%.1f' start 2 interval 30 font ',8'\n", f);
	fprintf(f, "set xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]\n", m->v0[0], m->v0[m->nv - 1],
		m->h_r0[0], m->h_r0[m->nh - 1]);
	map_tics(f, "x", m->v0, m->nv);
	map_tics(f, "y", m->h_r0, m->nh);
	fputs("$map << EOD\n", f);
	for (size_t ih = 0; ih < m->nh; ih++) {
		for (size_t iv = 0; iv < m->nv; iv++) {
			double v = m->rf[ih * m->nv + iv];
			fprintf(f, "%.6g %.6g ", m->v0[iv], m->h_r0[ih]);
			fprintf(f, isfinite(v) ? "%.6g\n" : "NaN\n", v);
		}
		fputc('\n', f);
	}
	fputs("EOD\n"
	      "splot $map using 1:2:3 with pm3d notitle, \\\n"
	      "      $map using 1:2:3 with lines nosurface lc rgb '#ffffff' lw 1 notitle, \\\n"
	      "      $map using 1:2:3 with labels nosurface tc rgb '#ffffff' notitle\n", f);
	return fflush(f) == 0 && !ferror(f) ? ANVIL_OK : ANVIL_EIO;
}

int plot_rf_map_save(const struct plot_rf_map *m, const struct plot_opts *o, const char *path,
		     const char *script_path, struct anvil_err *err)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *mf = open_memstream(&buf, &len);
	int st = mf ? plot_rf_map_write(mf, m, o) : ANVIL_ENOMEM;
	if (mf && fclose(mf) != 0 && !st)
		st = ANVIL_ENOMEM;
	if (st == ANVIL_EINVAL)
		anvil_err_set(err, st, "restitution-map: nothing to draw (a grid of at least 2 velocities x "
			      "2 thicknesses with a finite R_f is needed)");
	else if (st)
		anvil_err_set(err, st, "restitution-map: %s", anvil_strerror(st));
	else
		st = plot_emit(buf, len, o, path, script_path, err);
	free(buf);
	return st;
}
