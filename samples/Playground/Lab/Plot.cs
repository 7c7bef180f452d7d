using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace MagnusBall.Playground.Lab
{
    /// <summary>
    /// A view onto two coordinates of the flight (downrange against height, or downrange against side), mapped
    /// into an SVG box with a margin for the axis labels. Scales differ per axis: a tennis ball rises 3 m over 24 m.
    /// </summary>
    public sealed class Plot
    {
        /// <summary>SVG width, user units.</summary>
        public const double Width = 800;

        /// <summary>Margin left of and below the plot, for the labels.</summary>
        public const double Margin = 34;

        /// <summary>A view of width <see cref="Width"/> and <paramref name="height"/> over the given data ranges.</summary>
        public Plot(double height, double minX, double maxX, double minV, double maxV)
        {
            Height = height;
            MinX = minX;
            MaxX = maxX > minX ? maxX : minX + 1;
            MinV = minV;
            MaxV = maxV > minV ? maxV : minV + 1;
        }

        /// <summary>SVG height, user units.</summary>
        public double Height { get; }

        /// <summary>Data range across, m.</summary>
        public double MinX { get; }

        /// <summary>Data range across, m.</summary>
        public double MaxX { get; }

        /// <summary>Data range up the screen, m.</summary>
        public double MinV { get; }

        /// <summary>Data range up the screen, m.</summary>
        public double MaxV { get; }

        /// <summary>Screen x of data x.</summary>
        public double SX(double x) => Margin + (x - MinX) / (MaxX - MinX) * (Width - Margin - 8);

        /// <summary>Screen y of data v (up the screen).</summary>
        public double SY(double v) => Height - Margin - (v - MinV) / (MaxV - MinV) * (Height - Margin - 8);

        /// <summary>Data x of screen x.</summary>
        public double DataX(double sx) => MinX + (sx - Margin) / (Width - Margin - 8) * (MaxX - MinX);

        /// <summary>Data v of screen y.</summary>
        public double DataV(double sy) => MinV + (Height - Margin - sy) / (Height - Margin - 8) * (MaxV - MinV);

        /// <summary>The SVG path data of the points, taking x and v from each with the given selectors.</summary>
        public string PathData(IReadOnlyList<Vector3d> points, Func<Vector3d, double> x, Func<Vector3d, double> v)
        {
            var d = new StringBuilder(points.Count * 16);
            for (int i = 0; i < points.Count; i++)
            {
                d.Append(i == 0 ? 'M' : 'L').Append(N(SX(x(points[i])))).Append(',').Append(N(SY(v(points[i])))).Append(' ');
            }

            return d.ToString().TrimEnd();
        }

        /// <summary>About six round tick values across [min, max].</summary>
        public static IEnumerable<double> Ticks(double min, double max)
        {
            double span = max - min;
            double raw = span / 6;
            double magnitude = Math.Pow(10, Math.Floor(Math.Log10(raw)));
            double step = raw / magnitude < 2 ? 2 * magnitude : raw / magnitude < 5 ? 5 * magnitude : 10 * magnitude;
            for (double t = Math.Ceiling(min / step) * step; t <= max + 1e-9; t += step)
            {
                yield return Math.Abs(t) < 1e-12 ? 0 : t;
            }
        }

        /// <summary>A screen coordinate as SVG writes it (invariant, two decimals).</summary>
        public static string N(double value) => value.ToString("0.##", CultureInfo.InvariantCulture);
    }
}
