using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Shots;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// Writes docs/figures/net-cord-clip.svg (docs/contacts.md): side views of tennis balls meeting the net at the centre, from a
    /// clean pass to a clip of the cord that dribbles over, a clip that falls back, and a ball caught by the mesh. Not a test: run
    /// it by name (<c>dotnet test tests/MagnusBall.Tests --filter Name=WriteNetCordFigure</c>); it prints each path's events.
    /// </summary>
    [TestFixture]
    [Explicit("Figure generator for docs/contacts.md; run by name.")]
    public class NetCordFigure
    {
        private const double MinX = 8, MaxX = 16, MinZ = 0, MaxZ = 1.6;
        private const double Left = 60, Top = 40, Width = 640, Height = 256;

        /// <summary>The four balls' start heights over the cord's top plus the fall to the net, m (drop and lift move them about 7 cm lower).</summary>
        internal static readonly double[] Offsets = { 0.15, 0.06, 0.03, -0.05 };

        private static readonly string[] Labels = { "clears the net", "clips the cord, goes over", "clips the cord, falls back", "into the mesh" };

        /// <summary>Flies one ball from 8 m, 17 m/s, level, 1500 rpm topspin, aimed to pass the net `offset` above the cord's top.</summary>
        internal static List<FlightState> Path(double offset, List<FlightEvent> events)
        {
            FlightModel model = ContactShapeTests.Tennis();
            ContactShape[] net = SportShapes.TennisNet(0, new Vector3d(11.885, 0, 0), Vector3d.UnitY, Vector3d.UnitZ);
            var court = new GroundContact(MagnusBall.Contact.CrossBounce.Hard, new Plane(Vector3d.Zero, Vector3d.UnitZ));
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, court, net);
            // Aim: the ball falls about 0.5 g t^2 + drag/lift over the 0.23 s to the net; start high enough to arrive at cord + offset.
            double z0 = 0.914 + model.Ball.Radius + offset + 0.255;
            stepper.Reset(new FlightState(new Vector3d(MinX, 0, z0), new Vector3d(17, 0, 0), new Vector3d(0, 157, 0)));
            var path = new List<FlightState> { stepper.State };
            for (int i = 0; i < 240 * 2 && !stepper.IsStopped; i++)
            {
                stepper.TryStep(1.0 / 240);
                foreach (FlightEvent e in stepper.Events)
                {
                    events.Add(e);
                }

                path.Add(stepper.State);
                if (stepper.State.Position.X > MaxX || stepper.State.Position.X < MinX)
                {
                    break;
                }
            }

            return path;
        }

        [Test]
        [Explicit("Figure generator for docs/contacts.md; run by name.")]
        public void WriteNetCordFigure()
        {
            string path = System.IO.Path.Combine(BounceFigure.RepositoryRoot(), "docs", "figures", "net-cord-clip.svg");
            var svg = new StringBuilder();
            svg.Append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"760\" height=\"340\" font-family=\"sans-serif\" font-size=\"12\">\n");
            svg.Append("<rect width=\"760\" height=\"340\" fill=\"white\"/>\n");
            svg.Append(F("<text x=\"{0}\" y=\"22\" font-size=\"14\">Tennis balls at the net's centre (17 m/s, 1500 rpm topspin): side view, metres</text>\n", Left));
            svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"black\"/>\n", Left, Y(0), Left + Width));
            // The net: mesh up to the cord, the cord's circle.
            svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#888\" stroke-width=\"2\" stroke-dasharray=\"3,2\"/>\n", X(11.885), Y(0), Y(0.894)));
            svg.Append(F("<circle cx=\"{0}\" cy=\"{1}\" r=\"{2}\" fill=\"#444\"/>\n", X(11.885), Y(0.904), 0.01 * Width / (MaxX - MinX)));
            string[] colours = { "#1f77b4", "#2ca02c", "#d62728", "#9467bd" };
            for (int k = 0; k < Offsets.Length; k++)
            {
                var events = new List<FlightEvent>();
                List<FlightState> states = Path(Offsets[k], events);
                var points = new StringBuilder();
                foreach (FlightState s in states)
                {
                    points.Append(F("{0},{1} ", X(s.Position.X), Y(s.Position.Z)));
                }

                svg.Append($"<polyline points=\"{points}\" fill=\"none\" stroke=\"{colours[k]}\" stroke-width=\"1.5\"/>\n");
                svg.Append(F("<text x=\"{0}\" y=\"{1}\" fill=\"{2}\">{3}</text>\n", Left + Width - 190, Top + 14 + 16 * k, colours[k], Labels[k]));
                foreach (FlightEvent e in events)
                {
                    if (e.Kind == FlightEventKinds.Contact)
                    {
                        svg.Append(F("<circle cx=\"{0}\" cy=\"{1}\" r=\"{2}\" fill=\"none\" stroke=\"{3}\"/>\n", X(e.Position.X), Y(e.Position.Z), 0.033 * Width / (MaxX - MinX), colours[k]));
                    }

                    TestContext.Out.WriteLine($"offset {Offsets[k]:0.00}: {e.Kind} id {e.ShapeId} t {e.Time:0.0000} x {e.Position.X:0.000} z {e.Position.Z:0.000} v {e.Velocity.Length:0.00} -> {e.After.Velocity.Length:0.00} m/s (vx {e.After.Velocity.X:0.00})");
                }
            }

            svg.Append("</svg>\n");
            File.WriteAllText(path, svg.ToString());
        }

        private static double X(double x) => Left + (x - MinX) / (MaxX - MinX) * Width;

        private static double Y(double z) => Top + (MaxZ - z) / (MaxZ - MinZ) * Height;

        private static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
