% Mobility: the Grubler-Kutzbach count (1) against the rank of the
% constraint Jacobian (3).  Planar linkages in natural coordinates: the
% moving joints' x, y; each link a fixed distance, a slider a fixed height.
% P: points (fixed first), nf: how many are fixed, C: distance pairs, S: slider point
a1 = [0.10806046117362795 0.16829419696157930];   % the crank pin at 1 rad, 0.2 m
switch linkage
  case 'four-bar'
    n = 4; j1 = 4; j2 = 0; nf = 2; P = [0 0; 0.6 0; a1; 0.55 0.4]; C = [1 3; 3 4; 2 4]; S = 0;
  case 'slider-crank'
    n = 4; j1 = 4; j2 = 0; nf = 1; P = [0 0; a1/2; 0.45 0]; C = [1 2; 2 3]; S = 3;
  case 'five-bar'
    n = 5; j1 = 5; j2 = 0; nf = 2; P = [0 0; 0.5 0; 0.054353 0.139806; 0.25 0.45; 0.465919 0.146089];
    C = [1 3; 3 4; 4 5; 5 2]; S = 0;
  case 'watt-six-bar'
    n = 6; j1 = 7; j2 = 0; nf = 3; P = [0 0; 0.6 0; 1.1 0.1; a1; 0.55 0.4; 0.8 0.3; 1.0 0.55];
    C = [1 4; 4 5; 2 5; 2 6; 5 6; 6 7; 7 3]; S = 0;
  case 'stephenson-six-bar'
    n = 6; j1 = 7; j2 = 0; nf = 3; P = [0 0; 0.6 0; 0.9 0.3; a1; 0.55 0.4; 0.35 0.55; 0.75 0.75];
    C = [1 4; 4 5; 2 5; 4 6; 5 6; 6 7; 7 3]; S = 0;
  case 'double-parallelogram'
    n = 5; j1 = 6; j2 = 0; nf = 3; P = [0 0; 0.6 0; 0.3 0.1; a1; a1 + [0.6 0]; a1 + [0.3 0.1]];
    C = [1 4; 2 5; 3 6; 4 5; 4 6; 5 6]; S = 0;
  case 'triangle'
    n = 3; j1 = 3; j2 = 0; nf = 2; P = [0 0; 0.6 0; 0.25 0.4]; C = [1 3; 2 3]; S = 0;
  case 'custom'
    n = links;
end
if strcmp(linkage, 'bennett')
  % spatial: 4 links, 4 revolutes: M = 6 (n - 1) - 5 j1   (2)
  out.gruebler = 6*(4 - 1) - 4*(6 - 1);
  % the joint axes by Denavit-Hartenberg at th1 = 1, th2 from Bennett's relation
  al = pi/3; be = pi/4; A = 0.3; B = A*sin(be)/sin(al);
  th1 = 1; th2 = 2*atan(sin((be + al)/2)/sin((be - al)/2) / tan(th1/2));
  th = [th1 th2 -th1 -th2]; av = [A B A B]; alv = [al be al be];
  T = eye(4); Tw = zeros(6, 4);
  for k = 1:4
    z = T(1:3, 3); o = T(1:3, 4);
    Tw(:, k) = [z; cross(o, z)];           % the joint's twist
    T = T * [cos(th(k)) -sin(th(k))*cos(alv(k)) sin(th(k))*sin(alv(k)) av(k)*cos(th(k));
             sin(th(k))  cos(th(k))*cos(alv(k)) -cos(th(k))*sin(alv(k)) av(k)*sin(th(k));
             0 sin(alv(k)) cos(alv(k)) 0; 0 0 0 1];
  end
  fprintf('the loop closes: |T1 T2 T3 T4 - I| = %.2g\n', max(max(abs(T - eye(4)))));
  out.coordinates = 4;                     % the joint angles
  out.constraints = 6;                     % a loop in space closes in 6 equations
  out.rank = rank(Tw);
  out.mobility = 4 - out.rank;
  out.count_wrong = out.mobility ~= out.gruebler;
elseif strcmp(linkage, 'custom')
  out.gruebler = 3*(n - 1) - 2*j1 - j2;    % (1)
else
  out.gruebler = 3*(n - 1) - 2*j1 - j2;    % (1)
  np = size(P, 1);  nq = 2*(np - nf);
  J = zeros(size(C, 1) + (S > 0), nq);     % Jacobian of |Pi - Pj|^2 - L^2 and of y_S - y0
  for r = 1:size(C, 1)
    i = C(r, 1);  j = C(r, 2);  d = P(i, :) - P(j, :);
    if i > nf, J(r, 2*(i - nf) - 1:2*(i - nf)) = 2*d; end
    if j > nf, J(r, 2*(j - nf) - 1:2*(j - nf)) = -2*d; end
  end
  if S > 0
    J(end, 2*(S - nf)) = 1;
  end
  out.coordinates = nq;
  out.constraints = size(J, 1);
  out.rank = rank(J);                      % by singular values
  out.mobility = nq - out.rank;            % (3)
  out.count_wrong = out.mobility ~= out.gruebler;
end
