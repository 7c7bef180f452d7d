using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;

namespace MagnusBall.Cli
{
    /// <summary>Writes flight results as the JSON and CSV formats of docs/cli.md.</summary>
    internal static class ResultWriter
    {
        /// <summary>
        /// {"results": [{"name", "landing", "apex", "crossings", "steps", "derivativeEvaluations"}]}, plus
        /// "contacts" for a scenario with shapes and "samples" when <paramref name="samples"/> is given.
        /// </summary>
        public static string Json(IReadOnlyList<FlightResult> results, int? samples)
        {
            return JsonOutput.Write(w =>
            {
                w.WriteStartObject();
                w.WriteStartArray("results");
                foreach (FlightResult r in results)
                {
                    w.WriteStartObject();
                    w.WriteString("name", r.Scenario.Name);
                    if (r.Landing is FlightState landing)
                    {
                        w.WriteStartObject("landing");
                        w.WriteNumber("time", landing.Time);
                        WriteVector(w, "position", landing.Position);
                        WriteVector(w, "velocity", landing.Velocity);
                        w.WriteEndObject();
                    }
                    else
                    {
                        w.WriteNull("landing");
                    }

                    if (r.Apex is FlightState apex)
                    {
                        w.WriteStartObject("apex");
                        w.WriteNumber("time", apex.Time);
                        WriteVector(w, "position", apex.Position);
                        w.WriteEndObject();
                    }
                    else
                    {
                        w.WriteNull("apex");
                    }

                    w.WriteStartArray("crossings");
                    foreach (Crossing c in r.Crossings)
                    {
                        w.WriteStartObject();
                        w.WriteString("name", c.Name);
                        w.WriteNumber("time", c.State.Time);
                        WriteVector(w, "position", c.State.Position);
                        if (c.Inside is bool inside)
                        {
                            w.WriteBoolean("inside", inside);
                        }

                        w.WriteEndObject();
                    }

                    w.WriteEndArray();
                    if (r.Scenario.Shapes is { Count: > 0 })
                    {
                        // Issue 40: every touch of a shape, in time order (the field is absent for a scenario without shapes).
                        w.WriteStartArray("contacts");
                        foreach (MagnusBall.Flight.FlightEvent c in r.Contacts ?? System.Array.Empty<MagnusBall.Flight.FlightEvent>())
                        {
                            w.WriteStartObject();
                            w.WriteNumber("shapeId", c.ShapeId);
                            w.WriteNumber("time", c.State.Time);
                            WriteVector(w, "position", c.State.Position);
                            WriteVector(w, "normal", c.ContactNormal);
                            WriteVector(w, "velocity", c.State.Velocity);
                            WriteVector(w, "velocityAfter", c.After.Velocity);
                            WriteVector(w, "angularVelocityAfter", c.After.AngularVelocity);
                            w.WriteEndObject();
                        }

                        w.WriteEndArray();
                    }

                    w.WriteNumber("steps", r.Steps);
                    w.WriteNumber("derivativeEvaluations", r.DerivativeEvaluations);
                    if (samples is int n)
                    {
                        w.WriteStartArray("samples");
                        foreach (FlightState s in Sample(r, n))
                        {
                            w.WriteStartObject();
                            w.WriteNumber("time", s.Time);
                            WriteVector(w, "position", s.Position);
                            WriteVector(w, "velocity", s.Velocity);
                            w.WriteEndObject();
                        }

                        w.WriteEndArray();
                    }

                    w.WriteEndObject();
                }

                w.WriteEndArray();
                w.WriteEndObject();
            });
        }

        /// <summary>
        /// CSV with a header line "scenario,time,x,y,z,vx,vy,vz,wx,wy,wz": every step's state (ending at the
        /// landing) or, with <paramref name="samples"/>, that many states evenly spaced in time.
        /// </summary>
        public static string Csv(IReadOnlyList<FlightResult> results, int? samples)
        {
            var text = new StringBuilder("scenario,time,x,y,z,vx,vy,vz,wx,wy,wz\n");
            foreach (FlightResult r in results)
            {
                string name = CsvField(r.Scenario.Name);
                foreach (FlightState s in samples is int n ? Sample(r, n) : Steps(r))
                {
                    text.Append(name);
                    foreach (double value in new[]
                             {
                                 s.Time, s.Position.X, s.Position.Y, s.Position.Z, s.Velocity.X, s.Velocity.Y, s.Velocity.Z,
                                 s.AngularVelocity.X, s.AngularVelocity.Y, s.AngularVelocity.Z,
                             })
                    {
                        text.Append(',').Append(value.ToString("R", CultureInfo.InvariantCulture));
                    }

                    text.Append('\n');
                }
            }

            return text.ToString();
        }

        /// <summary><paramref name="count"/> states evenly spaced from launch to the end (landing or maxTime), on the interpolant.</summary>
        public static IEnumerable<FlightState> Sample(FlightResult r, int count)
        {
            foreach (double t in ScenarioFlight.SampleTimes(r.Scenario.Initial.Time, r.End.Time, count))
            {
                yield return r.At(t);
            }
        }

        /// <summary>The integrator's own states up to the end, then the end state (the landing, if it landed).</summary>
        public static IEnumerable<FlightState> Steps(FlightResult r)
        {
            foreach (StepPoint p in r.Points!)
            {
                if (p.State.Time >= r.End.Time)
                {
                    break;
                }

                yield return p.State;
            }

            yield return r.End;
        }

        private static void WriteVector(Utf8JsonWriter w, string name, Vector3d v)
        {
            w.WriteStartArray(name);
            w.WriteNumberValue(v.X);
            w.WriteNumberValue(v.Y);
            w.WriteNumberValue(v.Z);
            w.WriteEndArray();
        }

        private static string CsvField(string value) =>
            value.IndexOfAny(new[] { ',', '"', '\n', '\r' }) >= 0 ? "\"" + value.Replace("\"", "\"\"") + "\"" : value;
    }
}
