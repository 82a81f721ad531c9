% Green's theorem over the edges, eqs. (2)-(4), from the mean vertex.
x = polygon(:, 1) - mean(polygon(:, 1));
y = polygon(:, 2) - mean(polygon(:, 2));
x1 = circshift(x, -1);              % the next vertex, round the outline
y1 = circshift(y, -1);
c = x .* y1 - x1 .* y;
A = sum(c) / 2;
s = sign(A);                        % +1 counter-clockwise, -1 clockwise
A = s * A;
Sx = s * sum((x + x1) .* c) / 6;
Sy = s * sum((y + y1) .* c) / 6;
Sxx = s * sum((x.^2 + x .* x1 + x1.^2) .* c) / 12;
Syy = s * sum((y.^2 + y .* y1 + y1.^2) .* c) / 12;
Sxy = s * sum((x .* y1 + 2 * x .* y + 2 * x1 .* y1 + x1 .* y) .* c) / 24;
xr = Sx / A;
yr = Sy / A;
parts = [A, xr + mean(polygon(:, 1)), yr + mean(polygon(:, 2)), ...
         Syy - A * yr^2, Sxx - A * xr^2, Sxy - A * xr * yr, 1];
% discs: r > 0 added, r < 0 a hole (eq. 5)
for k = 1:size(circles, 1)
  r = abs(circles(k, 3));
  parts(end + 1, :) = [pi * r^2, circles(k, 1), circles(k, 2), pi * r^4 / 4, pi * r^4 / 4, 0, sign(circles(k, 3))];
end
sg = parts(:, 7);
out.area = sum(sg .* parts(:, 1));
out.xc = sum(sg .* parts(:, 1) .* parts(:, 2)) / out.area;
out.yc = sum(sg .* parts(:, 1) .* parts(:, 3)) / out.area;
dx = parts(:, 2) - out.xc;
dy = parts(:, 3) - out.yc;
out.Ixx = sum(sg .* (parts(:, 4) + parts(:, 1) .* dy.^2));
out.Iyy = sum(sg .* (parts(:, 5) + parts(:, 1) .* dx.^2));
out.Ixy = sum(sg .* (parts(:, 6) + parts(:, 1) .* dx .* dy));
% principal axes, eq. (7)
R = sqrt(((out.Ixx - out.Iyy) / 2)^2 + out.Ixy^2);
out.I1 = (out.Ixx + out.Iyy) / 2 + R;
out.I2 = (out.Ixx + out.Iyy) / 2 - R;
out.alpha = atan2(-2 * out.Ixy, out.Ixx - out.Iyy) / 2;
if out.alpha <= -pi / 2
  out.alpha = out.alpha + pi;
end
out.orientation = s;
