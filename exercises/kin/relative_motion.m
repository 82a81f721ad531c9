% A slider on a turntable: absolute velocity (2) and acceleration (3) as
% the relative motion plus the table's (transport) motion plus Coriolis.
th = theta0 + omega*t + 0.5*alpha*t^2;     w = omega + alpha*t;
s = s0 + u*t + 0.5*b*t^2;                   sd = u + b*t;
Rt = [cos(th) -sin(th); sin(th) cos(th)];   % table axes -> ground axes
r = Rt * [s; h];                            % position (1)
perp = @(x) [-x(2); x(1)];                  % k x (.)
v_rel = Rt * [sd; 0];
v_tr = w * perp(r);                          % w x r
v = v_rel + v_tr;                            % (2)
a_rel = Rt * [b; 0];
a_tt = alpha * perp(r);                      % alpha x r
a_tn = -w^2 * r;                             % w x (w x r)
a_cor = 2 * w * perp(v_rel);                 % Coriolis
a = a_rel + a_tt + a_tn + a_cor;             % (3)
out.v_rel = norm(v_rel);  out.v_transport = norm(v_tr);  out.v = norm(v);
out.a_rel = norm(a_rel);  out.a_transport_t = norm(a_tt);  out.a_transport_n = norm(a_tn);
out.a_coriolis = norm(a_cor);  out.a = norm(a);
% the check: the second difference of the absolute position
pos = @(q) [cos(theta0 + omega*q + 0.5*alpha*q^2) -sin(theta0 + omega*q + 0.5*alpha*q^2);
            sin(theta0 + omega*q + 0.5*alpha*q^2)  cos(theta0 + omega*q + 0.5*alpha*q^2)] * [s0 + u*q + 0.5*b*q^2; h];
hh = 1e-3;
a_fd = (pos(t + hh) - 2*pos(t) + pos(t - hh)) / hh^2;
fprintf('|a - second difference| = %.2g; without the Coriolis term it would be %.3g\n', ...
        norm(a - a_fd), norm(a - a_cor - a_fd));
