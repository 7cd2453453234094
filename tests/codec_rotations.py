"""codec_rotations.py ASF AMC [EPS_RAD]: would a compressed clip be smaller with a
3-dof joint's rotation stored as its quaternion's x y z (w from the unit length)
instead of its Euler angles? Per joint, each way quantised with the largest step
(one for the three tracks) that keeps the joint's rotation within EPS_RAD (default
0.002) of the source on every frame, then costed as the codec codes a track: the
best of predictors 0-2 with the best Rice parameter (app/codec). A measuring tool
(python3-numpy; ../shared/tools/acl-bench/acclaim.py reads the clip), not part of
the build; app/codec/README.md gives its figures."""
import os, sys, numpy as np
shared = os.environ.get('SKP_SHARED', os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'shared'))
sys.path.insert(0, os.path.join(shared, 'tools', 'acl-bench'))
import acclaim as A
asf, amc = sys.argv[1:3]
sk = A.parse_asf(asf); names = A.topo(sk)
frames = [d for _, d in A.parse_amc(amc)]
def qmul(a,b):
    w1,x1,y1,z1=a; w2,x2,y2,z2=b
    return np.array([w1*w2-x1*x2-y1*y2-z1*z2,w1*x2+x1*w2+y1*z2-z1*y2,w1*y2-x1*z2+y1*w2+z1*x2,w1*z2+x1*y2-y1*x2+z1*w2])
def mat(b, vals):
    M=np.eye(3)
    for ch,v in zip(b.dof, vals):
        if ch in ('rx','ry','rz'): M=A.rot(ch[1], sk.ang(v)) @ M
    return b.C @ M @ b.C.T
def angerr(R1,R2):
    c=(np.trace(R1.T@R2)-1)/2; return np.arccos(np.clip(c,-1,1))
def rice(q):
    best=None
    for order in range(3):
        r=np.diff(q,n=order) if order else q.copy()
        z=np.where(r>=0,2*r,-2*r-1)
        for k in range(0,20):
            c=np.sum(z>>k)+len(z)*(1+k)
            best=c if best is None or c<best else best
    return best
def qmat(q):
    w,x,y,z=q
    return np.array([[1-2*(y*y+z*z),2*(x*y-w*z),2*(x*z+w*y)],[2*(x*y+w*z),1-2*(x*x+z*z),2*(y*z-w*x)],[2*(x*z-w*y),2*(y*z+w*x),1-2*(x*x+y*y)]])
def mat2q(m):
    w=np.sqrt(max(0,1+m[0,0]+m[1,1]+m[2,2]))/2
    if w>1e-6: return np.array([w,(m[2,1]-m[1,2])/(4*w),(m[0,2]-m[2,0])/(4*w),(m[1,0]-m[0,1])/(4*w)])
    # a half turn: from the largest diagonal
    x=np.sqrt(max(0,1+m[0,0]-m[1,1]-m[2,2]))/2
    return np.array([(m[2,1]-m[1,2])/(4*x),x,(m[0,1]+m[1,0])/(4*x),(m[0,2]+m[2,0])/(4*x)])
eps=float(sys.argv[3]) if len(sys.argv)>3 else 0.002
tot_e=tot_q=0
for n in names:
    b=sk.bones[n]
    rot=[c for c in b.dof if c in ('rx','ry','rz')]
    if len(rot)!=3: continue
    E=np.array([[sk.ang(v) for c,v in zip(b.dof,d.get(n,[])) if c in('rx','ry','rz')] for d in frames])
    R=[mat(b,[v for c,v in zip(b.dof,d.get(n,[]))]) for d in frames]
    Q=np.array([mat2q(r) for r in R]); Q[Q[:,0]<0]*=-1
    def err_e(s):
        qe=np.round(E/s); back=qe*s
        worst=0
        for i in range(len(frames)):
            M=np.eye(3)
            for j,ch in enumerate(rot): M=A.rot(ch[1],back[i,j])@M
            worst=max(worst,angerr(R[i],b.C@M@b.C.T))
        return worst,qe.astype(np.int64)
    def err_q(s):
        qv=np.round(Q[:,1:]/s); v=qv*s
        worst=0
        for i in range(len(frames)):
            w=np.sqrt(max(0,1-np.dot(v[i],v[i])))
            worst=max(worst,angerr(R[i],qmat(np.array([w,*v[i]]))))
        return worst,qv.astype(np.int64)
    def search(f):
        lo,hi=1e-6,1.0
        for _ in range(30):
            m=np.sqrt(lo*hi)
            if f(m)[0]<=eps: lo=m
            else: hi=m
        return f(lo)[1]
    be=sum(rice(c) for c in search(err_e).T); bq=sum(rice(c) for c in search(err_q).T)
    tot_e+=be; tot_q+=bq
    print("%-12s euler %7.2f  quat %7.2f bits/frame  %s"%(n,be/len(frames),bq/len(frames),"quat smaller" if bq<be else ""))
print("total 3-dof joints: euler %.1f quat %.1f bits/frame (%d frames, max rotation error %.4f rad each)"%(tot_e/len(frames),tot_q/len(frames),len(frames),eps))
