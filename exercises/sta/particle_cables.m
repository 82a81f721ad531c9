% Equilibrium of the ring: sum of T_i u_i + P = 0, eq. (1).
n = size(anchors, 1);
U = zeros(3, n);
for i = 1:n
  d = anchors(i, :) - ring;
  U(:, i) = d' / norm(d);            % unit vector from the ring to anchor i
end
if n == 3
  T = U \ (-load');                  % eq. (2)
else
  nrm = cross(U(:, 1), U(:, 2));  nrm = nrm / norm(nrm);
  e2 = cross(nrm, U(:, 1));          % the cables' plane: e1 = u1, e2
  A = [U(:, 1)' * U(:, 1), U(:, 1)' * U(:, 2); e2' * U(:, 1), e2' * U(:, 2)];
  T = A \ (-[U(:, 1)' * load'; e2' * load']);
end
for i = 1:n
  out.(sprintf('T%d', i)) = T(i);
  if T(i) < 0
    fprintf('cable %d would have to push: a cable can only pull\n', i);
  end
end
out.T_max = max(T);
