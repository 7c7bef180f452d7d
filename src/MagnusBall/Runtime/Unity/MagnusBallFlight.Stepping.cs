// MagnusBallFlight, the frame side: Update or FixedUpdate hands the frame's time to the driver, the transform follows
// the render state, and the step's events are raised (C# events and UnityEvents). The flight itself is in MagnusBallFlight.cs.
#nullable enable
using System;
using System.Collections.Generic;
using MagnusBall.Flight;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Integration;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using UnityEngine;
using UnityEngine.Events;

namespace MagnusBall.Components
{
    public partial class MagnusBallFlight : MonoBehaviour
    {
        private void Update()
        {
            if (_driver == null)
            {
                return;
            }

            if (stepIn == StepIn.Update && _flying)
            {
                Step(Time.deltaTime);
            }
            else if (stepIn == StepIn.Update && _driver.IsFinished)
            {
                // The flight is over, but the drawn ball runs a step behind it: the finished driver takes no step and lets the
                // render state run on to where the flight ended (else it would stay drawn up to a step short of the landing).
                _driver.Advance(Time.deltaTime);
            }

            if (_driver == null)
            {
                return; // an event handler cancelled the flight
            }

            // Update: the state interpolated between the last two fixed steps. FixedUpdate: the latest fixed
            // state (the ball moves in FixedUpdate-sized hops, as a non-interpolated Rigidbody does).
            FlightState render = stepIn == StepIn.Update ? _driver.RenderState : _driver.State;
            transform.position = UnityFrame.ToUnity(render.Position);
            if (rotateWithSpin && _flying)
            {
                double rate = render.AngularVelocity.Length;
                if (rate > 0)
                {
                    // Unity rotates by the left-hand rule, the convention the spin is in: the axis goes in unchanged.
                    // NormalizedOrZero, not w / rate: that multiplies by 1/rate, +inf below 5.6e-309 rad/s (a NaN axis).
                    // Taken modulo a turn in double: a huge spin's angle does not fit a float (AngleAxis(inf) is a NaN rotation).
                    double turn = rate * Time.deltaTime * (180.0 / Math.PI);
                    float degrees = double.IsFinite(turn) ? (float)(turn % 360.0) : 0f; // beyond a double: no meaningful angle
                    transform.rotation = Quaternion.AngleAxis(degrees, UnityFrame.ToUnity(render.AngularVelocity.NormalizedOrZero())) * transform.rotation;
                }
            }
        }

        private void FixedUpdate()
        {
            if (stepIn == StepIn.FixedUpdate && _flying && _driver != null)
            {
                Step(Time.fixedDeltaTime);
            }
        }

        private void Step(float frameDelta)
        {
            FixedStepDriver driver = _driver!;
            AdvanceResult result = driver.Advance(frameDelta, _events);
            // The buffer holds any one step's events, so none is lost: where the next step's might not fit, the driver
            // defers the rest of the frame, taken here after the events are raised. Bounded: each pass takes at least one
            // step of the frame's time, and at most MaxStepsPerAdvance passes are made.
            for (int pass = 0; ; pass++)
            {
                FlightEvent[] events = _events; // a relaunch in a handler may replace the buffer
                for (int i = 0; i < result.EventCount && _driver == driver; i++)
                {
                    Raise(events[i]); // not the old flight's later events once a handler relaunched or cancelled
                }

                if (!result.StepsDeferred || pass >= driver.MaxStepsPerAdvance || _driver != driver)
                {
                    break;
                }

                result = driver.Advance(0, _events);
            }

            if (_driver == driver)
            {
                _flying = !driver.IsFinished; // (a handler that relaunched or cancelled has set it for its own flight)
            }
        }
    }
}
