// MagnusBallFlight, the events raised to C# and UnityEvent listeners and the checks of a configuration before it is used. The flight itself is in MagnusBallFlight.cs.
#nullable enable
using System;
using MagnusBall.Flight;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Integration;
using MagnusBall.Stepping;
using UnityEngine;

namespace MagnusBall.Components
{
    public partial class MagnusBallFlight
    {
        // The one place that knows the driver's event type: adapt here when it changes.
        private void Raise(in FlightEvent e)
        {
            switch (e.Kind)
            {
                case FlightEventKinds.Landing:
                    Raise(Landed, onLanded, e);
                    break;
                case FlightEventKinds.Bounce:
                    _segmentStart = e.After;
                    _segmentVersion++;
                    Raise(Bounced, onBounced, e);
                    break;
                case FlightEventKinds.PlaneCrossing:
                    Raise(PlaneCrossed, onPlaneCrossed, e);
                    break;
                case FlightEventKinds.Apex:
                    Raise(ApexReached, onApex, e);
                    break;
                case FlightEventKinds.Rest:
                    Raise(Stopped, onStopped, e);
                    break;
                case FlightEventKinds.Contact:
                    _segmentStart = e.After; // a new arc starts at the hit, as at a bounce
                    _segmentVersion++;
                    Raise(Contacted, onContact, e);
                    break;
            }
        }

        // The C# event, then the UnityEvent, unless a C# handler relaunched or cancelled the flight.
        private void Raise(Action<FlightEvent>? csharp, FlightEventUnityEvent? unity, in FlightEvent e)
        {
            FixedStepDriver? driver = _driver;
            csharp?.Invoke(e);
            if (_driver == driver)
            {
                unity?.Invoke(e);
            }
        }

        private void EnsureConfigured()
        {
            if (_model == null)
            {
                ApplySettings();
            }
        }

        private void Set(FlightModel model, IIntegrator integratorToUse, double step, FlightEventSet events, IBounceModel? bounce, double maxFrame, ContactShape[]? shapes)
        {
            CheckConfiguration(model, integratorToUse, step, events, bounce, maxFrame, shapes);
            Assign(model, integratorToUse, step, events, bounce, maxFrame, shapes);
        }

        private static void CheckConfiguration(
            FlightModel model, IIntegrator integratorToUse, double step, FlightEventSet events, IBounceModel? bounce, double maxFrame, ContactShape[]? shapes)
        {
            if (model == null)
            {
                throw new ArgumentNullException(nameof(model));
            }

            if (integratorToUse == null)
            {
                throw new ArgumentNullException(nameof(integratorToUse));
            }

            if (events == null)
            {
                throw new ArgumentNullException(nameof(events));
            }

            // The driver checks the numbers (fixed step, clamp, a ground for the bounce) and names them.
            _ = new FixedStepDriver(model, integratorToUse, step, new FlightState(Vector3d.Zero, Vector3d.Zero, Vector3d.Zero), events, bounce, maxFrame, shapes: shapes);
            if (!(step <= maxFrame))
            {
                // Frames are cut to the clamp, so a longer step is never reached: the ball would hang at its start.
                throw new ArgumentOutOfRangeException(
                    "fixedStep", step, FormattableString.Invariant($"fixedStep ({step} s) must be at most the frame-time clamp maxFrameDelta ({maxFrame} s)."));
            }
        }

        private void Assign(FlightModel model, IIntegrator integratorToUse, double step, FlightEventSet events, IBounceModel? bounce, double maxFrame, ContactShape[]? shapes)
        {
            _shapes = shapes;
            _model = model;
            _integrator = integratorToUse;
            _fixedStep = step;
            _eventSet = events;
            _bounce = bounce;
            _maxFrameDelta = maxFrame;
        }

        private static void RequireField(Vector3 value, string name)
        {
            if (float.IsNaN(value.x) || float.IsInfinity(value.x) || float.IsNaN(value.y) || float.IsInfinity(value.y) ||
                float.IsNaN(value.z) || float.IsInfinity(value.z))
            {
                throw new ArgumentException(FormattableString.Invariant($"{name} must be finite; got ({value.x}, {value.y}, {value.z})."), name);
            }
        }

        private static void RequireField(float value, string name)
        {
            if (float.IsNaN(value) || float.IsInfinity(value))
            {
                throw new ArgumentOutOfRangeException(name, value, FormattableString.Invariant($"{name} must be finite; got {value}."));
            }
        }

        private static void RequireFinite(double value, string name)
        {
            if (double.IsNaN(value) || double.IsInfinity(value))
            {
                throw new ArgumentOutOfRangeException(
                    name, value, $"{name} must be a finite number; got {value.ToString("R", System.Globalization.CultureInfo.InvariantCulture)}.");
            }
        }
    }
}
