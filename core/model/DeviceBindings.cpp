#include "model/DeviceBindings.h"

#include <QSettings>
#include <QStringList>
#include <algorithm>

namespace stellwerk::model {

namespace {

// Every key of the bindings, in one place. An entry is one line: "accessory;orc;target;output" (output
// -1: none), "accessory;ro;module;relay", "contact;orc;uid;input", "contact;ro;module;input".
const QString group = QStringLiteral("deviceBindings");
const QString accessoriesKey = QStringLiteral("accessories");
const QString contactsKey = QStringLiteral("contacts");
const QString orcKind = QStringLiteral("orc");
const QString roKind = QStringLiteral("ro");
const QChar separator = QLatin1Char(';');

QString textOf(const AccessoryBinding& binding) {
    if (const auto* orc = std::get_if<OrcOutput>(&binding.output))
        return QStringList{QString::number(binding.accessory), orcKind, QString::number(orc->target),
                           QString::number(orc->output ? int(*orc->output) : -1)}
            .join(separator);
    const auto& ro = std::get<RoRelay>(binding.output);
    return QStringList{QString::number(binding.accessory), roKind, ro.module, QString::number(ro.relay)}.join(
        separator);
}

QString textOf(const ContactBinding& binding) {
    if (const auto* orc = std::get_if<OrcInput>(&binding.input))
        return QStringList{QString::number(binding.contact), orcKind, QString::number(orc->encoderUid),
                           QString::number(orc->input)}
            .join(separator);
    const auto& ro = std::get<RoInput>(binding.input);
    return QStringList{QString::number(binding.contact), roKind, ro.module, QString::number(ro.input)}.join(
        separator);
}

// The four fields of a line, the first and last as numbers; nullopt when it has another shape.
struct Fields {
    qint64 key = 0;
    QString kind;
    QString device;
    int number = 0;
};

std::optional<Fields> fieldsOf(const QString& line) {
    const QStringList parts = line.split(separator);
    if (parts.size() != 4)
        return std::nullopt;
    bool keyOk = false;
    bool numberOk = false;
    Fields fields{parts[0].toLongLong(&keyOk), parts[1], parts[2], parts[3].toInt(&numberOk)};
    if (!keyOk || !numberOk || (fields.kind != orcKind && fields.kind != roKind) || fields.device.isEmpty())
        return std::nullopt;
    return fields;
}

std::optional<AccessoryBinding> accessoryOf(const QString& line) {
    const auto fields = fieldsOf(line);
    if (!fields)
        return std::nullopt;
    if (fields->kind == roKind)
        return AccessoryBinding{fields->key, RoRelay{fields->device, fields->number}};
    bool ok = false;
    const uint target = fields->device.toUInt(&ok);
    if (!ok || target > 0xFFFF || fields->number > 7)
        return std::nullopt;
    OrcOutput output{std::uint16_t(target), std::nullopt};
    if (fields->number >= 0)
        output.output = std::uint8_t(fields->number);
    return AccessoryBinding{fields->key, output};
}

std::optional<ContactBinding> contactOf(const QString& line) {
    const auto fields = fieldsOf(line);
    if (!fields || fields->key < 0 || fields->key > 0xFFFFFFFF)
        return std::nullopt;
    const auto key = ContactKey(fields->key);
    if (fields->kind == roKind)
        return ContactBinding{key, RoInput{fields->device, fields->number}};
    bool ok = false;
    const uint uid = fields->device.toUInt(&ok);
    if (!ok || fields->number < 0 || fields->number > 31)
        return std::nullopt;
    return ContactBinding{key, OrcInput{uid, fields->number}};
}

} // namespace

const AccessoryBinding* DeviceBindings::accessory(std::int64_t id) const {
    const auto found =
        std::find_if(accessories.begin(), accessories.end(),
                     [id](const AccessoryBinding& binding) { return binding.accessory == id; });
    return found == accessories.end() ? nullptr : &*found;
}

const ContactBinding* DeviceBindings::contact(ContactKey key) const {
    const auto found = std::find_if(contacts.begin(), contacts.end(),
                                    [key](const ContactBinding& binding) { return binding.contact == key; });
    return found == contacts.end() ? nullptr : &*found;
}

DeviceBindings DeviceBindings::demo() {
    const QString module = QStringLiteral("Demo RO");
    DeviceBindings demo;
    demo.accessories.push_back({1, RoRelay{module, 1}});
    demo.accessories.push_back({6, OrcOutput{0x0101, 0}});
    demo.contacts.push_back({contactKey(0, 9), OrcInput{0x3A2E0102, 0}});
    demo.contacts.push_back({contactKey(0, 20), RoInput{module, 1}});
    return demo;
}

DeviceBindings DeviceBindings::load(QSettings& settings) {
    DeviceBindings bindings;
    settings.beginGroup(group);
    for (const QString& line : settings.value(accessoriesKey).toStringList())
        if (auto binding = accessoryOf(line))
            bindings.accessories.push_back(std::move(*binding));
    for (const QString& line : settings.value(contactsKey).toStringList())
        if (auto binding = contactOf(line))
            bindings.contacts.push_back(std::move(*binding));
    settings.endGroup();
    return bindings;
}

void DeviceBindings::save(QSettings& settings) const {
    QStringList accessoryLines;
    for (const AccessoryBinding& binding : accessories)
        accessoryLines << textOf(binding);
    QStringList contactLines;
    for (const ContactBinding& binding : contacts)
        contactLines << textOf(binding);
    settings.beginGroup(group);
    settings.setValue(accessoriesKey, accessoryLines);
    settings.setValue(contactsKey, contactLines);
    settings.endGroup();
}

} // namespace stellwerk::model
