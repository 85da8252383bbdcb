/* TEMPORARY (helper writes the real one) */
#include "beltdyn/boom.h"
#include <math.h>
static double cubic_v(double u){ return u<=0?0:(u>=1?1:3*u*u-2*u*u*u); }
static double cubic_a(double u){ return (u<=0||u>=1)?0:6*u-6*u*u; }
static double cubic_int(double u){ if(u<=0)return 0; if(u>=1)u=1; return u*u*u-0.5*u*u*u*u; }
void bd_boom_stroke_eval(const bd_boom_stroke_def *s, double t, double *st, double *v, double *a)
{
    if (s->kind == BD_STROKE_TABLE) {
        const bd_table *tb=&s->table; *st=bd_table_eval(tb,t); *v=0; *a=0;
        for(int i=0;i+1<tb->n;i++) if(t>=tb->t[i]&&t<tb->t[i+1]) *v=(tb->v[i+1]-tb->v[i])/(tb->t[i+1]-tb->t[i]);
        return;
    }
    double ta=s->accel_time, th=s->hold_time, td=s->decel_time, V=s->v_max, dir=s->direction;
    double x=0, vv=0, aa=0;
    if (t < ta) { double u=t/ta; vv=V*cubic_v(u); aa=V*cubic_a(u)/ta; x=V*ta*cubic_int(u); }
    else if (t < ta+th) { vv=V; x=V*ta*0.5+V*(t-ta); }
    else if (t < ta+th+td) { double u=(t-ta-th)/td; vv=V*(1-cubic_v(u)); aa=-V*cubic_a(u)/td; x=V*ta*0.5+V*th+V*td*(u-cubic_int(u)); }
    else { x=V*ta*0.5+V*th+V*td*0.5; }
    *st=s->initial+dir*x; *v=dir*vv; *a=dir*aa;
}
double bd_boom_stroke_end(const bd_boom_stroke_def *s)
{
    if (s->kind==BD_STROKE_TABLE) return s->table.n? s->table.t[s->table.n-1]:0;
    return s->accel_time+s->hold_time+s->decel_time;
}
