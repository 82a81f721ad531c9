% The sliding ladder: A = (L cos(theta), 0) on the floor moves at vA,
% B = (0, L sin(theta)) on the wall.  Angular velocity and acceleration (2),
% instantaneous centre, velocity (3) and acceleration (4) of P = A + s (B - A).
perp = @(x) [-x(2); x(1)];                 % k x (.)
A = [L*cos(theta); 0];  B = [0; L*sin(theta)];  P = A + s*(B - A);
out.omega = vA / (L*sin(theta));           % from d/dt (L cos(theta)) = vA
out.alpha = out.omega^2 * cos(theta)/sin(theta);
out.v_B = -L*cos(theta)*out.omega;
out.a_B = -L*(cos(theta)*out.alpha + sin(theta)*out.omega^2);
% the instantaneous centre: normals to v_A (vertical through A) and v_B
% (horizontal through B) meet at I
I = [A(1); B(2)];
out.ic_x = I(1);  out.ic_y = I(2);
vP = out.omega * perp(P - I);              % (3)
aP = out.alpha * perp(P - A) - out.omega^2 * (P - A);   % (4), a_A = 0
out.vPx = vP(1);  out.vPy = vP(2);  out.v_P = norm(vP);
out.aPx = aP(1);  out.aPy = aP(2);  out.a_P = norm(aP);
out.pole_x = A(1);  out.pole_y = A(2);     % A moves at constant speed: a_A = 0
% check by differences: move A on by +-h seconds
Pt = @(tau) [(1 - s)*(L*cos(theta) + vA*tau); s*L*sin(acos((L*cos(theta) + vA*tau)/L))];
h = 1e-4;
fprintf('|v_P - central difference| = %.2g m/s\n', norm(vP - (Pt(h) - Pt(-h))/(2*h)));
