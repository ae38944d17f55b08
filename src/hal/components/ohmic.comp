component ohmic "Ohmic plate sensing for plasma torches, measured with a Mesa THCAD";
pin in float thcad-0-volt-freq "THCAD output frequency at 0 V, in Hz, from its calibration label";
pin in float thcad-max-volt-freq "THCAD output frequency at full scale, in Hz, from its calibration label";
pin in float thcad-divide = 32 "Frequency divider selected on the THCAD (1, 32, 64 or 128)";
pin in float thcad-fullscale = 5 "THCAD full-scale input voltage (5, 10 or 300)";
pin in float volt-divider = 4.9 "Ratio of any external voltage divider in front of the THCAD";
pin in float ohmic-threshold = 22 "Sensed voltage at or above which contact is reported";
pin in float ohmic-low = 21 "Sensed voltage below which contact is released";
pin in float velocity-in "Divided THCAD frequency in Hz, e.g. a Mesa encoder velocity with scale 1";
pin in bit is-probing "TRUE while probing; ohmic-on stays FALSE otherwise";
pin out float ohmic-volts "Sensed voltage";
pin out bit ohmic-on "TRUE while the torch touches the plate";
variable int contact;
function _ "Convert the frequency to volts and detect contact";
license "GPL";
author "OpenEMC";
description """
The THCAD turns the sensing voltage into a frequency between
thcad-0-volt-freq and thcad-max-volt-freq, divided by thcad-divide.  This
component multiplies velocity-in back by thcad-divide, maps the 0 V..full
scale frequency range onto 0..thcad-fullscale volts and multiplies by
volt-divider to give ohmic-volts.  While is-probing is TRUE, ohmic-on turns
on when ohmic-volts reaches ohmic-threshold and off again only when it falls
below ohmic-low (hysteresis); outside probing ohmic-on is FALSE.
""";
;;
/* Volts at the sensing input for the measured (divided) frequency; 0 if uncalibrated. */
static double ohmic_volts_from(double freq, double f0, double fmax, double divide,
                               double fullscale, double ratio)
{
    double span = fmax - f0;
    if (span == 0.0 || divide <= 0.0) return 0.0;
    return (freq * divide - f0) / span * fullscale * ratio;
}

/* Compute the sensed voltage and the contact state with hysteresis. */
FUNCTION(_)
{
    double v = ohmic_volts_from(velocity_in, thcad_0_volt_freq, thcad_max_volt_freq,
                                thcad_divide, thcad_fullscale, volt_divider);
    ohmic_volts = v;
    if (!is_probing) contact = 0;
    else if (v >= ohmic_threshold) contact = 1;
    else if (v < ohmic_low) contact = 0;
    ohmic_on = contact;
}
