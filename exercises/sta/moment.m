% Moment of F at r about O, eq. (1), and about the axis u through O, eq. (3).
w = r - O;
M = [w(2) * F(3) - w(3) * F(2), w(3) * F(1) - w(1) * F(3), w(1) * F(2) - w(2) * F(1)];
out.Mx = M(1);
out.My = M(2);
out.Mz = M(3);
out.M = norm(M);
t = dot(w, F) / dot(F, F);          % foot of the perpendicular from O on the line
out.d = norm(w - t * F);            % lever arm, eq. (2): |M| = |F| d
e = u / norm(u);
out.M_axis = dot(e, M);
