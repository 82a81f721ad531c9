% Coulomb friction at its limit: closed forms, and the equilibrium solved.
if strcmp(setup, 'block')
  out.P_up = W * (sin(alpha) + mu * cos(alpha));               % eq. (2)
  out.P_hold = max(0, W * (sin(alpha) - mu * cos(alpha)));     % eq. (3)
  out.P_tip = W * (w * cos(alpha) + h * sin(alpha)) / (2 * hP);  % eq. (4)
  out.first = 1 + (out.P_tip < out.P_up);                      % 1 slides, 2 tips
  out.alpha_slip = atan(mu);
  out.alpha_tip = atan(w / h);
  % eq. (5): unknowns P, N, N*xN with friction at its limit
  x = [1 -mu 0; 0 1 0; -hP 0 1] \ [W * sin(alpha); W * cos(alpha); W * (w * cos(alpha) - h * sin(alpha)) / 2];
  fprintf('at P_up the normal force acts %.6g m along the base of %.6g m\n', x(3) / x(2), w);
else
  phi = atan(mu);
  out.P_in = W * tan(beta + 2 * phi);                          % eq. (6)
  out.P_out = W * tan(beta - 2 * phi);                         % eq. (7)
  out.self_locking = beta < 2 * phi;
  sb = sin(beta);  cb = cos(beta);
  A = [0 sb + mu * cb -1 0; 0 cb - mu * sb -mu 0; -mu -(sb + mu * cb) 0 1; 1 -(cb - mu * sb) 0 0];
  x = A \ [0; W; 0; 0];                                        % eq. (8): N1 N2 N3 P
  out.N1 = x(1);  out.N2 = x(2);  out.N3 = x(3);
end
