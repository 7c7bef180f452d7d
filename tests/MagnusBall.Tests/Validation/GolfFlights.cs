using System;
using System.Collections.Generic;
using System.Linq;
using System.Text.Json;
using MagnusBall.Presets;
using MagnusBall.Tests.Presets;

namespace MagnusBall.Tests.Validation
{
    /// <summary>One golf flight: a measured launch and the measured (or TrackMan-normalised) outcome.</summary>
    internal sealed class GolfShot
    {
        public string Name = "";
        public string Group = "";
        public double Speed;        // m/s
        public double Elevation;    // deg above horizontal
        public double Azimuth;      // deg, + right of the target line
        public double SpinRpm;
        public double SpinAxis;     // deg, + tilts the lift to the right (fade)
        public double Carry;        // m along the target line
        public double? Apex;        // m
        public double? LandAngle;   // deg below horizontal
    }

    /// <summary>What a simulated golf shot did.</summary>
    internal readonly struct GolfResult
    {
        public GolfResult(double carry, double side, double apex, double landAngle, double time)
        {
            Carry = carry;
            Side = side;
            Apex = apex;
            LandAngle = landAngle;
            Time = time;
        }

        public double Carry { get; }

        public double Side { get; }

        public double Apex { get; }

        public double LandAngle { get; }

        public double Time { get; }
    }

    /// <summary>
    /// Reads the golf flights in data/published and flies them: z up, x the target line, y to the left (so
    /// "right" is -y), launched from the ground, stopped where the centre comes back to the launch height.
    /// RK4 at 1 ms (ShotFlight; its error is far below every tolerance here).
    /// </summary>
    internal static class GolfFlights
    {
        public const double Yard = ShotFlight.MetresPerYard;

        /// <summary>TrackMan's normalisation air: 77 degF (25 degC), 0 ft (101325 Pa), dry.</summary>
        public static Air TrackManAir { get; } = Air.FromWeather(25, 101325, 0);

        public static List<GolfShot> Session()
        {
            JsonElement root = PublishedCases.Load("golf-trackman-session.json");
            var shots = new List<GolfShot>();
            foreach (JsonElement s in root.GetProperty("shots").EnumerateArray())
            {
                JsonElement l = s.GetProperty("launch");
                JsonElement m = s.GetProperty("measured");
                shots.Add(new GolfShot
                {
                    Name = s.GetProperty("name").GetString()!.Replace("TM session ", ""),
                    Group = "session",
                    Speed = l.Number("speed_mps"),
                    Elevation = l.Number("elevation_deg"),
                    Azimuth = l.Number("azimuth_deg_right"),
                    SpinRpm = l.Number("spin_rpm"),
                    SpinAxis = l.Number("spin_axis_deg_right"),
                    Carry = m.Number("carry_m"),
                    Apex = m.Number("apex_m"),
                    LandAngle = m.Number("land_angle_deg"),
                });
            }

            return shots;
        }

        public static List<GolfShot> TourAverages()
        {
            JsonElement root = PublishedCases.Load("trackman-tour-averages.json");
            var shots = new List<GolfShot>();
            foreach (JsonElement s in root.GetProperty("shots").EnumerateArray())
            {
                shots.Add(new GolfShot
                {
                    Name = s.GetProperty("name").GetString()!,
                    Group = s.GetProperty("group").GetString()!,
                    Speed = s.Number("ball_speed_mph") * ShotFlight.MetresPerSecondPerMph,
                    Elevation = s.Number("launch_deg"),
                    SpinRpm = s.Number("spin_rpm"),
                    Carry = s.Number("carry_yd") * Yard,
                    Apex = s.TryGetProperty("max_height_yd", out JsonElement h) ? h.GetDouble() * Yard : (double?)null,
                    LandAngle = s.TryGetProperty("land_angle_deg", out JsonElement a) ? a.GetDouble() : (double?)null,
                });
            }

            return shots;
        }

        public static GolfResult Fly(SportPreset preset, GolfShot shot, Air air)
        {
            Vector3d up = Vector3d.UnitZ;
            double e = shot.Elevation * Math.PI / 180, a = shot.Azimuth * Math.PI / 180;
            Vector3d velocity = new Vector3d(Math.Cos(e) * Math.Cos(a), -Math.Cos(e) * Math.Sin(a), Math.Sin(e)) * shot.Speed;
            Vector3d along = velocity.NormalizedOrZero();
            Vector3d lift = (up - along * Vector3d.Dot(up, along)).NormalizedOrZero();
            Vector3d side = Vector3d.Cross(along, up).NormalizedOrZero(); // to the right of the flight
            double t = shot.SpinAxis * Math.PI / 180;
            Vector3d curve = lift * Math.Cos(t) + side * Math.Sin(t);
            Vector3d spin = Spin.Toward(velocity, curve, Spin.FromRpm(shot.SpinRpm));
            FlightModel model = preset.CreateModel(air, Gravity.ZUp);
            ShotOutcome o = ShotFlight.Fly(model, new FlightState(Vector3d.Zero, velocity, spin));
            return new GolfResult(o.Landing.X, -o.Landing.Y, o.Apex, ShotFlight.LandingAngleDegrees(o, up), o.Time);
        }

        public static double Median(IEnumerable<double> values)
        {
            double[] v = values.OrderBy(x => x).ToArray();
            return v.Length % 2 == 1 ? v[v.Length / 2] : 0.5 * (v[v.Length / 2 - 1] + v[v.Length / 2]);
        }
    }
}
