from program import *
seen=set(); feats={}
for blk in blocks():
    a=assignment(blk,F2)
    if a in seen: continue
    seen.add(a)
    s1=proj_sq(F1,ID); s2=proj_sq(F2,a); lo=max(s1[2],s2[2]); hi=min(s1[2],s2[2]); x=float(blk['d0'])**2
    Rm=run_block(a,x,-1); Rp=run_block(a,x,1)
    f=Rm['f']
    F={}
    F['x/lo']=x/lo; F['(x-lo)/(lo-hi)']=(x-lo)/(lo-hi); F['x-lo']=x-lo; F['x-hi']=x-hi
    for nm,R in (('m',Rm),('p',Rp)):
        F['b2'+nm]=R['b2']; F['g2'+nm]=R['g2']; F['b2/x'+nm]=R['b2']/x; F['g2/x'+nm]=R['g2']/x
        F['zQ1'+nm]=R['zQ1']; F['zQ2'+nm]=R['zQ2']; F['zT1'+nm]=R['zT1']; F['zT2'+nm]=R['zT2']
        F['b2-g2-x'+nm]=R['b2']-R['g2']-x
    F['b2p-b2m']=Rp['b2']-Rm['b2']; F['b2p/b2m']=Rp['b2']/Rm['b2']; F['g2p/g2m']=Rp['g2']/Rm['g2']
    F['disc/x2']=Rm['disc']/x**2; F['disc']=Rm['disc']
    F['b2m+b2p']=Rm['b2']+Rp['b2']; F['(b2m+b2p)/x']=(Rm['b2']+Rp['b2'])/x
    feats[a]=F
keys=list(next(iter(feats.values())).keys())
for k in keys:
    v=np.array([feats[a][k] for a in feats])
    print('%-16s cv=%.3g  %s'%(k, np.std(v)/abs(np.mean(v)) if np.mean(v)!=0 else np.inf, np.array2string(v,precision=4,max_line_width=250)))
